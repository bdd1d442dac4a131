// SPDX-License-Identifier: GPL-3.0-or-later
// `vesselview-cli centerline`: a stenosis phantom written to a file comes
// back as VTK polylines with VMTK's array names and the right values, a CSV
// of sections and JSON with the stenosis; a surface in metres is warned
// about; a wall folded by noise is smoothed unless --smooth-folded off; a
// surface that cannot be analysed exits 3 with the reason.
#include <gtest/gtest.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkXMLPolyDataReader.h>

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "CliRun.h"
#include "vv/demo/TubePhantom.h"
#include "vv/meshio/MeshLoader.h"
#include "vv/meshio/MeshWriter.h"

namespace {

using vv::test::runCli;

std::filesystem::path scratch() {
    auto dir = vv::test::processTestDir("centerline");
    std::filesystem::create_directories(dir);
    return dir;
}

std::filesystem::path writePhantom(const std::string& name, double scale = 1.0,
                                   double jitter = 0.0) {
    vv::demo::TubePhantomOptions o;
    o.shape = vv::demo::TubeShape::Stenosis;
    o.radiusMm = 5.0;
    o.lengthMm = 100.0;
    o.stenosisLengthMm = 20.0;
    o.stenosisPercent = 50.0;
    o.targetTriangles = 40'000;
    o.jitterFraction = jitter;
    vv::scene::Mesh mesh = vv::demo::makeTubePhantom(o).mesh;
    for (auto& p : mesh.positions) {
        p *= static_cast<float>(scale);
    }
    auto file = scratch() / name;
    vv::meshio::writeVtp(mesh, file);
    return file;
}

TEST(CenterlineCommand, WritesVmtkArraysSectionsAndJson) {
    const auto input = writePhantom("stenosis.vtp");
    const auto output = scratch() / "centerlines.vtp";
    const auto csv = scratch() / "sections.csv";
    const auto surface = scratch() / "branches.vtp";
    const auto run = runCli({"centerline", input.string(), "-o", output.string(), "--sections",
                             csv.string(), "--surface-out", surface.string(), "--json"});
    ASSERT_EQ(run.code, 0) << run.err;
    // The surface with its branch ids, as the categorical-label path reads it.
    const vv::scene::Mesh labelled = vv::meshio::loadMesh(surface);
    const auto* ids = labelled.pointArray("branch_id");
    ASSERT_NE(ids, nullptr);
    EXPECT_TRUE(ids->integer);
    EXPECT_EQ(ids->finiteRange(), (std::make_optional(std::pair<float, float>{0.0F, 0.0F})));
    ASSERT_TRUE(labelled.labelNames.contains("branch_id"));
    EXPECT_EQ(labelled.labelNames.at("branch_id").at(0), "branch 0");

    auto reader = vtkSmartPointer<vtkXMLPolyDataReader>::New();
    reader->SetFileName(output.c_str());
    reader->Update();
    vtkPolyData* lines = reader->GetOutput();
    ASSERT_EQ(lines->GetNumberOfLines(), 1);
    const vtkIdType n = lines->GetNumberOfPoints();
    ASSERT_GT(n, 150);  // 100 mm every 0.5 mm
    for (const char* name :
         {"MaximumInscribedSphereRadius", "Abscissas", "Curvature", "Torsion",
          "ParallelTransportNormals", "branch_id", "CenterlineSectionArea", "EquivalentDiameter",
          "CenterlineSectionMinSize", "CenterlineSectionMaxSize"}) {
        ASSERT_NE(lines->GetPointData()->GetArray(name), nullptr) << name;
    }
    vtkDataArray* abscissa = lines->GetPointData()->GetArray("Abscissas");
    vtkDataArray* radius = lines->GetPointData()->GetArray("MaximumInscribedSphereRadius");
    vtkDataArray* diameter = lines->GetPointData()->GetArray("EquivalentDiameter");
    EXPECT_NEAR(abscissa->GetTuple1(n - 1) - abscissa->GetTuple1(0), 100.0, 1.0);
    double narrowest = 1e9;
    for (vtkIdType i = 0; i < n; ++i) {
        const double s = abscissa->GetTuple1(i);
        if (s > 10.0 && s < 90.0) {
            narrowest = std::min(narrowest, diameter->GetTuple1(i));
        }
        if (s > 10.0 && s < 30.0) {
            EXPECT_NEAR(radius->GetTuple1(i), 5.0, 0.1);
            EXPECT_NEAR(diameter->GetTuple1(i), 10.0, 0.1);
        }
    }
    EXPECT_NEAR(narrowest, 5.0, 0.05);

    std::ifstream in(csv);
    std::string header;
    std::getline(in, header);
    EXPECT_EQ(header.rfind("branch_id,point,abscissa_mm,x_mm,y_mm,z_mm,area_mm2,"
                           "equivalent_diameter_mm,",
                           0),
              0U)
        << header;
    int rows = 0;
    for (std::string line; std::getline(in, line);) {
        ++rows;
    }
    EXPECT_EQ(rows, n);

    const QJsonObject json = QJsonDocument::fromJson(QByteArray::fromStdString(run.out)).object();
    const QJsonArray branches = json["branches"].toArray();
    ASSERT_EQ(branches.size(), 1);
    const QJsonObject stenosis = branches[0].toObject()["stenosis"].toObject();
    EXPECT_NEAR(stenosis["diameter_percent"].toDouble(), 50.0, 2.0) << run.out;
    EXPECT_NEAR(stenosis["area_percent"].toDouble(), 75.0, 2.0) << run.out;
    EXPECT_TRUE(stenosis["reference"].toString().startsWith("Automatic")) << run.out;
    EXPECT_NEAR(branches[0].toObject()["narrowest"].toObject()["equivalent_diameter_mm"].toDouble(),
                5.0, 0.05);
    EXPECT_TRUE(json["diameters"].toString().contains("Feret")) << run.out;
}

TEST(CenterlineCommand, WarnsAboutAMeshInMetresAndScalesIt) {
    const auto input = writePhantom("metres.vtp", 0.001);
    const auto output = scratch() / "metres-centerlines.vtp";
    const auto warned = runCli({"centerline", input.string(), "-o", output.string()});
    EXPECT_NE(warned.err.find("--scale 1000"), std::string::npos) << warned.err;
    const auto scaled =
        runCli({"centerline", input.string(), "-o", output.string(), "--scale", "1000", "--json"});
    ASSERT_EQ(scaled.code, 0) << scaled.err;
    EXPECT_EQ(scaled.err.find("--scale 1000"), std::string::npos) << scaled.err;
    const QJsonObject json =
        QJsonDocument::fromJson(QByteArray::fromStdString(scaled.out)).object();
    EXPECT_NEAR(json["branches"].toArray()[0].toObject()["length_mm"].toDouble(), 100.0, 1.0);
}

TEST(CenterlineCommand, ASurfaceThatCannotBeAnalysedExitsThreeWithTheReason) {
    const auto flat = scratch() / "flat.stl";
    {
        std::ofstream out(flat);
        out << "solid flat\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
               "vertex 0 1 0\nendloop\nendfacet\nendsolid flat\n";
    }
    const auto output = scratch() / "flat-centerlines.vtp";
    const auto run = runCli({"centerline", flat.string(), "-o", output.string()});
    EXPECT_EQ(run.code, 3);
    EXPECT_NE(run.err.find("flat.stl"), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("no inside"), std::string::npos) << run.err;
    EXPECT_FALSE(std::filesystem::exists(output));
}

// Noise of 10 % of r on 0.4 mm triangles: the wall folds over itself. It is
// smoothed by default (said on stderr) and measured: the length whole; with
// --smooth-folded off it is analysed as it is, and the note or the error
// says to smooth it.
TEST(CenterlineCommand, AFoldedWallIsSmoothedUnlessToldNotTo) {
    const auto input = writePhantom("folded.vtp", 1.0, 0.1);
    const auto output = scratch() / "folded-centerlines.vtp";
    const auto smoothed = runCli({"centerline", input.string(), "-o", output.string(), "--json"});
    ASSERT_EQ(smoothed.code, 0) << smoothed.err;
    EXPECT_NE(smoothed.err.find("it was smoothed before the analysis"), std::string::npos)
        << smoothed.err;
    const QJsonObject json =
        QJsonDocument::fromJson(QByteArray::fromStdString(smoothed.out)).object();
    EXPECT_NEAR(json["branches"].toArray()[0].toObject()["length_mm"].toDouble(), 100.0, 1.0);

    const auto asItIs =
        runCli({"centerline", input.string(), "-o", output.string(), "--smooth-folded", "off"});
    EXPECT_TRUE(asItIs.code == 0 || asItIs.code == 3) << asItIs.err;
    EXPECT_NE(asItIs.err.find("smooth the surface first"), std::string::npos) << asItIs.err;
    EXPECT_EQ(asItIs.err.find("it was smoothed"), std::string::npos) << asItIs.err;
}

TEST(CenterlineCommand, BadOptionsAreUsageErrors) {
    const auto input = writePhantom("options.vtp");
    EXPECT_EQ(runCli({"centerline", input.string(), "-o", "x.vtp", "--step", "0"}).code, 2);
    EXPECT_EQ(runCli({"centerline", input.string(), "-o", "x.vtp", "--source", "1,2"}).code, 2);
    EXPECT_EQ(runCli({"centerline", input.string(), "-o", "x.csv"}).code, 2);
    EXPECT_EQ(runCli({"centerline", input.string()}).code, 2);
    EXPECT_EQ(
        runCli({"centerline", input.string(), "-o", "x.vtp", "--smooth-folded", "maybe"}).code, 2);
}

}  // namespace
