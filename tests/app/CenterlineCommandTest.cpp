// SPDX-License-Identifier: GPL-3.0-or-later
// `vesselview-cli centerline`: a stenosis phantom written to a file comes
// back as VTK polylines with VMTK's array names and the right values, a CSV
// of sections and JSON with the stenosis; a surface in metres is warned
// about; a wall folded by noise is smoothed unless --smooth-folded off; a
// surface that cannot be analysed exits 3 with the reason; landmarks on the
// aneurysm phantom give their sections, lengths and the aortic sizing table.
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
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "CliRun.h"
#include "RunTool.h"
#include "common/MeasurementFile.h"
#include "vv/core/Error.h"
#include "vv/demo/AneurysmPhantom.h"
#include "vv/demo/TubePhantom.h"
#include "vv/dicom/Uid.h"
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
    // Landmarks: only with --json, a known key or free:NAME, three numbers.
    EXPECT_EQ(
        runCli({"centerline", input.string(), "-o", "x.vtp", "--landmark", "aneurysm_start=0,0,1"})
            .code,
        2);
    const auto unknown = runCli(
        {"centerline", input.string(), "-o", "x.vtp", "--json", "--landmark", "renal=0,0,1"});
    EXPECT_EQ(unknown.code, 2);
    EXPECT_NE(unknown.err.find("lowest_renal_artery"), std::string::npos) << unknown.err;
    EXPECT_EQ(
        runCli({"centerline", input.string(), "-o", "x.vtp", "--json", "--landmark", "free:=0,0,1"})
            .code,
        2);
    EXPECT_EQ(runCli({"centerline", input.string(), "-o", "x.vtp", "--json", "--landmark",
                      "aneurysm_start=0,0"})
                  .code,
              2);
}

/// The aneurysm phantom (20k triangles, closed: its source is the trunk's
/// tip at z = -10) written to a file.
std::filesystem::path writeAneurysm() {
    vv::demo::AneurysmPhantomOptions o;
    o.targetTriangles = 20'000;
    auto file = scratch() / "aneurysm.vtp";
    vv::meshio::writeVtp(vv::demo::makeAneurysmPhantom(o).mesh, file);
    return file;
}

QJsonObject runJson(const std::vector<std::string>& args, std::string* err = nullptr) {
    const auto run = runCli(args);
    EXPECT_EQ(run.code, 0) << run.err;
    if (err != nullptr) {
        *err = run.err;
    }
    return QJsonDocument::fromJson(QByteArray::fromStdString(run.out)).object();
}

// The landmarks at the phantom's truth: each one's section, the lengths
// between them and the sizing table, against the truth (the trunk r 10 mm
// widening from z 35 to a 40 mm sac at z 80, the axes meeting at z 170, the
// iliacs r 6 mm, 30 degrees either side of +z).
TEST(CenterlineCommand, LandmarksGiveTheirSectionsLengthsAndTheAorticSizingTable) {
    const auto input = writeAneurysm();
    const auto output = scratch() / "aneurysm-centerlines.vtp";
    std::string err;
    const QJsonObject json =
        runJson({"centerline", input.string(), "-o", output.string(), "--json", "--landmark",
                 "lowest_renal_artery=0,0,20", "--landmark", "aneurysm_start=0,0,35", "--landmark",
                 "largest_aneurysm_diameter=0,0,80", "--landmark", "aortic_bifurcation=0,0,170",
                 "--landmark", "left_internal_iliac_origin=-20,0,204.64", "--landmark",
                 "right_internal_iliac_origin=20,0,204.64", "--landmark", "free:clamp=30,0,60"},
                &err);
    const QJsonArray landmarks = json["landmarks"].toArray();
    ASSERT_EQ(landmarks.size(), 7);
    EXPECT_EQ(landmarks[0].toObject()["kind"].toString(), "lowest_renal_artery");
    EXPECT_EQ(landmarks[6].toObject()["name"].toString(), "clamp");
    EXPECT_EQ(landmarks[6].toObject()["kind"].toString(), "free");
    EXPECT_NEAR(landmarks[6].toObject()["given_distance_mm"].toDouble(), 30.0, 0.5);
    EXPECT_NE(err.find("'clamp'"), std::string::npos) << "outside its vessel: " << err;
    EXPECT_NEAR(landmarks[2].toObject()["section"].toObject()["equivalent_diameter_mm"].toDouble(),
                40.0, 0.4);
    EXPECT_EQ(json["landmark_pairs"].toArray().size(), 7 * 6 / 2);
    const QJsonObject first = json["landmark_pairs"].toArray()[0].toObject();
    EXPECT_NEAR(first["along_centreline_mm"].toDouble(), 15.0, 0.15);
    EXPECT_NEAR(first["straight_mm"].toDouble(), 15.0, 0.15);

    const QJsonObject sizing = json["aortic_sizing"].toObject();
    const auto value = [&](const char* name) { return sizing[name].toObject()["value"]; };
    const QJsonArray neck = sizing["neck_diameters"].toArray();
    ASSERT_EQ(neck.size(), 4);
    for (const auto& cell : neck) {
        EXPECT_NEAR(cell.toObject()["sizes"].toObject()["equivalent_diameter_mm"].toDouble(), 20.0,
                    0.2);
    }
    EXPECT_NEAR(value("neck_length_mm").toDouble(), 15.0, 0.15);
    EXPECT_NEAR(value("alpha_deg").toDouble(), 0.0, 1.0);
    EXPECT_NEAR(value("beta_deg").toDouble(), 0.0, 1.0);
    EXPECT_NEAR(value("largest_aneurysm").toObject()["max_diameter_mm"].toDouble(), 40.0, 0.4);
    // The bifurcation landmark went to the tree's bifurcation, on the trunk's axis.
    const double forkZ = landmarks[3].toObject()["position"].toArray()[2].toDouble();
    EXPECT_NEAR(forkZ, 170.0, 2.0);
    EXPECT_NEAR(value("renal_to_aortic_bifurcation_mm").toDouble(), forkZ - 20.0,
                0.01 * (forkZ - 20.0));
    for (const char* side : {"left", "right"}) {
        const std::string prefix(side);
        const double along =
            value((prefix + "_aortic_bifurcation_to_internal_iliac_mm").c_str()).toDouble();
        const double truth = (170.0 - forkZ) + 40.0;  // along the axes through where they meet
        EXPECT_NEAR(along, truth, 0.01 * truth) << side;
        EXPECT_NEAR(value((prefix + "_smallest_iliac").c_str())
                        .toObject()["equivalent_diameter_mm"]
                        .toDouble(),
                    12.0, 0.12)
            << side;
    }

    // Without the start of the aneurysm: the neck's length blank, and why.
    const QJsonObject partial =
        runJson({"centerline", input.string(), "-o", output.string(), "--json", "--landmark",
                 "lowest_renal_artery=0,0,20", "--landmark", "aortic_bifurcation=0,0,170"});
    const QJsonObject neckLength = partial["aortic_sizing"].toObject()["neck_length_mm"].toObject();
    EXPECT_TRUE(neckLength["value"].isNull());
    EXPECT_EQ(neckLength["blank_reason"].toString(), "landmark_missing");
    EXPECT_TRUE(neckLength["blank"].toString().contains("Start of the aneurysm"))
        << neckLength["blank"].toString().toStdString();
    // Free landmarks alone: their sections and lengths, no sizing table.
    const QJsonObject free =
        runJson({"centerline", input.string(), "-o", output.string(), "--json", "--landmark",
                 "free:a=0,0,20", "--landmark", "free:b=0,0,60"});
    EXPECT_FALSE(free.contains("aortic_sizing"));
    EXPECT_NEAR(free["landmark_pairs"].toArray()[0].toObject()["along_centreline_mm"].toDouble(),
                40.0, 0.4);
}

/// The aneurysm's centrelines with the preset landmarks and a free one, as
/// a measurement file.
std::filesystem::path writeMeasurementFile() {
    auto file = scratch() / "measurements.json";
    const auto run =
        runCli({"centerline", writeAneurysm().string(), "-o", (scratch() / "m.vtp").string(),
                "--json", "--landmark", "lowest_renal_artery=0,0,20", "--landmark",
                "aneurysm_start=0,0,35", "--landmark", "largest_aneurysm_diameter=0,0,80",
                "--landmark", "aortic_bifurcation=0,0,170", "--landmark",
                "left_internal_iliac_origin=-20,0,204.64", "--landmark",
                "right_internal_iliac_origin=20,0,204.64", "--landmark", "free:clamp=0,0,60"});
    EXPECT_EQ(run.code, 0) << run.err;
    std::ofstream(file) << run.out;
    return file;
}

// What `centerline --json` writes reads back as it was written, and its
// measurement groups make a valid TID 1500 report.
TEST(MeasurementFile, ReadsWhatCenterlineWroteAndMakesAValidStructuredReport) {
    const auto file = writeMeasurementFile();
    std::ifstream in(file);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const QJsonObject json = QJsonDocument::fromJson(QByteArray::fromStdString(text)).object();
    const vv::app::ReportMeasurements m = vv::app::readMeasurements(file);
    ASSERT_EQ(m.branches.size(), 3U);
    EXPECT_DOUBLE_EQ(m.branches[1].lengthMm,
                     json["branches"].toArray()[1].toObject()["length_mm"].toDouble());
    ASSERT_EQ(m.landmarks.size(), 7U);
    EXPECT_EQ(m.landmarks[6].name, "clamp");
    EXPECT_EQ(m.landmarks[3].kind, vv::planning::LandmarkKind::AorticBifurcation);
    ASSERT_TRUE(m.landmarks[2].section.has_value());
    EXPECT_NEAR(m.landmarks[2].section->equivalentDiameterMm, 40.0, 0.4);
    EXPECT_EQ(m.lengths.size(), 21U);
    ASSERT_TRUE(m.sizing.has_value());
    EXPECT_DOUBLE_EQ(
        m.sizing->neckLengthMm.value.value(),
        json["aortic_sizing"].toObject()["neck_length_mm"].toObject()["value"].toDouble());
    ASSERT_TRUE(m.sizing->smallestIliac[1].value.has_value());

    const auto groups = vv::app::measurementGroups(m);
    // Seven landmarks with sections, the lengths, the sizing, three branches.
    ASSERT_EQ(groups.size(), 7U + 1U + 1U + 3U);
    std::set<std::string> ids;
    for (const auto& g : groups) {
        EXPECT_TRUE(ids.insert(g.trackingId).second) << g.trackingId;
        EXPECT_FALSE(g.numbers.empty()) << g.trackingId;
    }
    vv::dicom::MeasurementReportContent content;
    content.groups = groups;
    vv::dicom::ExportStudy study;
    study.studyInstanceUid = vv::dicom::newUid();
    const auto sr = scratch() / "measurements-sr.dcm";
    vv::dicom::writeMeasurementReport(sr, content, study, {});
    std::string output;
    vv::test::runTool("dciodvfy '" + sr.string() + "'", output);
    EXPECT_EQ(output.find("Error"), std::string::npos) << output;
    ASSERT_EQ(vv::test::runTool("dsrdump +Pl '" + sr.string() + "'", output), 0) << output;
    for (const char* expected :
         {"Neck angulation beta, neck to aneurysm axis",
          "Lowest renal artery to aortic bifurcation, along the centreline", "Aortic sizing",
          "Lengths between landmarks", "clamp", "Smallest left iliac access diameter"}) {
        EXPECT_NE(output.find(expected), std::string::npos) << expected;
    }
}

// A file that is not a measurement file is an error naming it and saying
// what is wrong, and it stays as it was.
TEST(MeasurementFile, AnythingElseIsAClearErrorAndStaysUntouched) {
    std::ifstream in(writeMeasurementFile());
    const std::string good((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const auto replaced = [&good](const std::string& from, const std::string& to) {
        std::string text = good;
        const auto at = text.find(from);
        EXPECT_NE(at, std::string::npos) << from;
        return text.replace(at, from.size(), to);
    };
    const std::vector<std::pair<std::string, std::string>> cases{
        {"", "not JSON"},
        {R"({"branches": [])", "not JSON"},
        {"[1, 2]", "is not named"},
        {replaced("vesselview-measurements-1", "vesselview-measurements-9"), "is not named"},
        {replaced(R"("length_mm")", R"("length")"), "length_mm"},
        {replaced(R"("kind": "aortic_bifurcation")", R"("kind": "carina")"), "landmark kind"},
        {replaced(R"("along_centreline_mm": )", R"("along_centreline_mm": "x", "y": )"),
         "along_centreline_mm"},
    };
    for (std::size_t i = 0; i < cases.size(); ++i) {
        const auto file = scratch() / ("bad-" + std::to_string(i) + ".json");
        std::ofstream(file, std::ios::binary) << cases[i].first;
        try {
            static_cast<void>(vv::app::readMeasurements(file));
            ADD_FAILURE() << "no error for case " << i;
        } catch (const vv::FormatError& e) {
            EXPECT_NE(std::string(e.what()).find(cases[i].second), std::string::npos)
                << i << ": " << e.what();
            EXPECT_NE(std::string(e.what()).find(file.filename().string()), std::string::npos)
                << e.what();
        }
        std::ifstream back(file, std::ios::binary);
        EXPECT_EQ(
            std::string((std::istreambuf_iterator<char>(back)), std::istreambuf_iterator<char>()),
            cases[i].first)
            << "case " << i << " was changed";
    }
    // Huge (sparse) and missing files.
    const auto huge = scratch() / "huge.json";
    std::ofstream(huge) << "{";
    std::filesystem::resize_file(huge, 65ULL << 20U);
    EXPECT_THROW(static_cast<void>(vv::app::readMeasurements(huge)), vv::FormatError);
    EXPECT_THROW(static_cast<void>(vv::app::readMeasurements(scratch() / "no-such.json")),
                 vv::IoError);
}

}  // namespace
