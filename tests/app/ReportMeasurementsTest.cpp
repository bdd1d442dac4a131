// SPDX-License-Identifier: GPL-3.0-or-later
// `vesselview-cli report --measurements MEAS.json [--dicom-sr SR.dcm]`: the
// measurement file that `centerline --json --landmark ...` writes for the
// aneurysm phantom, shown in the PDF's Measurements section (read back with
// pdftotext, in English and in German) and sent as a TID 1500 Structured
// Report (checked by dciodvfy, read back by dsrdump and dcmdump), its
// evidence the source series of a DICOM input. Rendering needs OpenGL: run
// under `xvfb-run -a`.
#include <gtest/gtest.h>
#include <unistd.h>

#include <QColor>
#include <QImage>
#include <QLocale>
#include <QString>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "DicomTestUtil.h"
#include "ReportTestUtil.h"
#include "SyntheticCta.h"
#include "cli/Cli.h"
#include "common/MeasurementFile.h"
#include "vv/core/NumberText.h"
#include "vv/demo/AneurysmPhantom.h"
#include "vv/meshio/MeshWriter.h"

namespace report_measurements_test {

namespace {

namespace fs = std::filesystem;
using vv::shortestText;
using vv::report::test::pdfPages;
using vv::report::test::runTool;
using vv::report::test::withoutLigatures;

fs::path freshDir(const std::string& name) {
    fs::path dir =
        fs::path(VV_TEST_TMP) / "report-measurements" / (name + "-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

struct RunResult {
    int code;
    std::string out;
    std::string err;
};

RunResult cli(const std::vector<std::string>& args) {
    std::ostringstream out;
    std::ostringstream err;
    const int code = vv::cli::run(args, out, err);
    return {code, out.str(), err.str()};
}

/// The aneurysm phantom (20k triangles) and its measurement file with the
/// preset landmarks, or all but the start of the aneurysm.
struct Measured {
    fs::path mesh;
    fs::path json;
};

Measured measure(const fs::path& dir, bool withAneurysmStart = true) {
    vv::demo::AneurysmPhantomOptions o;
    o.targetTriangles = 20'000;
    Measured m{dir / "aneurysm.vtp", dir / "measurements.json"};
    vv::meshio::writeVtp(vv::demo::makeAneurysmPhantom(o).mesh, m.mesh);
    std::vector<std::string> args{"centerline",
                                  m.mesh.string(),
                                  "-o",
                                  (dir / "c.vtp").string(),
                                  "--json",
                                  "--landmark",
                                  "lowest_renal_artery=0,0,20",
                                  "--landmark",
                                  "largest_aneurysm_diameter=0,0,80",
                                  "--landmark",
                                  "aortic_bifurcation=0,0,170",
                                  "--landmark",
                                  "left_internal_iliac_origin=-20,0,204.64",
                                  "--landmark",
                                  "right_internal_iliac_origin=20,0,204.64"};
    if (withAneurysmStart) {
        args.insert(args.end(), {"--landmark", "aneurysm_start=0,0,35"});
    }
    const RunResult run = cli(args);
    EXPECT_EQ(run.code, 0) << run.err;
    std::ofstream(m.json) << run.out;
    return m;
}

std::string pdfText(const fs::path& pdf) {
    std::string text;
    EXPECT_EQ(runTool("pdftotext -layout '" + pdf.string() + "' -", text), 0) << text;
    // pdftotext writes no-break spaces as such; the checks use plain ones.
    std::string plain;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text.compare(i, 2, "\xc2\xa0") == 0) {
            plain += ' ';
            ++i;
        } else {
            plain += text[i];
        }
    }
    return plain;
}

/// The line of `text` that holds `label`, empty when none.
std::string lineWith(const std::string& text, const std::string& label) {
    const auto at = text.find(label);
    if (at == std::string::npos) {
        return {};
    }
    const auto start = text.rfind('\n', at);
    const auto end = text.find('\n', at);
    return text.substr(start == std::string::npos ? 0 : start + 1,
                       end == std::string::npos
                           ? std::string::npos
                           : end - (start == std::string::npos ? 0 : start + 1));
}

/// A length as the report prints it in `locale`: one decimal and "mm".
std::string millimetres(double value, const QLocale& locale) {
    return (locale.toString(value, 'f', 1) + QStringLiteral(" mm")).toStdString();
}

TEST(ReportMeasurements, ThePdfShowsTheFilesValuesAndTheSrCarriesThem) {
    const fs::path dir = freshDir("english");
    const Measured m = measure(dir);
    const vv::app::ReportMeasurements file = vv::app::readMeasurements(m.json);
    const RunResult r = cli({"report", m.mesh.string(), "-o", (dir / "r.pdf").string(), "--size",
                             "320x240", "--vss", "off", "--measurements", m.json.string(),
                             "--dicom-sr", (dir / "sr.dcm").string()});
    ASSERT_EQ(r.code, 0) << r.err;
    const std::string text = pdfText(dir / "r.pdf");
    ASSERT_NE(text.find("Measurements"), std::string::npos) << text;
    const QLocale english(QLocale::English);
    const auto& sizing = *file.sizing;
    const std::vector<std::pair<std::string, double>> rows{
        {"Neck length (lowest renal artery to start of the aneurysm)", *sizing.neckLengthMm.value},
        {"Lowest renal artery to aortic bifurcation", *sizing.renalToBifurcationMm.value},
        {"Aortic bifurcation to right internal iliac origin",
         *sizing.bifurcationToInternalIliacMm[1].value},
        {"Neck at the lowest renal artery", sizing.neckDiameters[0].value->equivalentDiameterMm},
        {"Largest aneurysm diameter", sizing.largestAneurysm.value->equivalentDiameterMm},
    };
    for (const auto& [label, value] : rows) {
        const std::string line = lineWith(text, label);
        EXPECT_NE(line.find(millimetres(value, english)), std::string::npos)
            << label << " should read " << millimetres(value, english) << ": " << line;
    }
    EXPECT_NE(text.find("2√(area/π)"), std::string::npos) << "the diameters are defined";
    // Numbers as the rest of the report writes them: no group separators (a
    // German reader could take "1.257" for a decimal point).
    const double area = sizing.largestAneurysm.value->areaMm2;
    ASSERT_GT(area, 1000.0);
    QLocale plain(QLocale::English);
    plain.setNumberOptions(QLocale::OmitGroupSeparator);
    EXPECT_NE(text.find(plain.toString(area, 'f', 0).toStdString() + " mm²"), std::string::npos)
        << text;
    EXPECT_EQ(text.find(english.toString(area, 'f', 0).toStdString() + " mm²"), std::string::npos)
        << "a group separator in " << english.toString(area, 'f', 0).toStdString();
    // The lengths between landmarks, by their names.
    const auto& first = file.lengths.front();
    EXPECT_NE(
        lineWith(text, first.from + " – " + first.to).find(millimetres(first.alongMm, english)),
        std::string::npos)
        << text;

    // The same values in the SR, which a PACS validates and reads.
    std::string output;
    runTool("dciodvfy '" + (dir / "sr.dcm").string() + "'", output);
    EXPECT_EQ(output.find("Error"), std::string::npos) << output;
    ASSERT_EQ(runTool("dsrdump +Pl '" + (dir / "sr.dcm").string() + "'", output), 0) << output;
    EXPECT_NE(output.find("\"" + vv::fixedText(*sizing.neckLengthMm.value, 3) +
                          "\" (mm,UCUM,\"millimeter\")"),
              std::string::npos)
        << output;
    EXPECT_NE(output.find("Neck length, lowest renal artery to start of the aneurysm"),
              std::string::npos);
}

TEST(ReportMeasurements, ABlankValueShowsADashAndWhyInEitherLanguage) {
    const fs::path dir = freshDir("blank");
    const Measured m = measure(dir, false);
    for (const bool german : {false, true}) {
        const fs::path pdf = dir / (german ? "de.pdf" : "en.pdf");
        std::string output;
        // The program itself: it finds the translations as installed.
        ASSERT_EQ(runTool(std::string("'") + VV_CLI_EXE + "' report '" + m.mesh.string() +
                              "' -o '" + pdf.string() + "' --size 320x240 --vss off --lang " +
                              (german ? "de" : "en") + " --measurements '" + m.json.string() + "'",
                          output),
                  0)
            << output;
        const std::string text = pdfText(pdf);
        const std::string label =
            german ? "Halslänge (unterste Nierenarterie bis Beginn des Aneurysmas)"
                   : "Neck length (lowest renal artery to start of the aneurysm)";
        EXPECT_NE(lineWith(text, label).find("—"), std::string::npos) << text;
        const std::string why = german ? "keine Landmarke „Beginn des Aneurysmas“ gesetzt"
                                       : "no landmark “Start of the aneurysm” is placed";
        EXPECT_NE(text.find(why), std::string::npos) << text;
        // A value present, in the language's numbers.
        const vv::app::ReportMeasurements file = vv::app::readMeasurements(m.json);
        const QLocale locale(german ? QLocale::German : QLocale::English);
        const std::string renal = german ? "Unterste Nierenarterie bis Aortenbifurkation"
                                         : "Lowest renal artery to aortic bifurcation";
        EXPECT_NE(lineWith(text, renal)
                      .find(millimetres(*file.sizing->renalToBifurcationMm.value, locale)),
                  std::string::npos)
            << text;
    }
}

TEST(ReportMeasurements, TheSrOfADicomSeriesListsItsInstancesAsEvidence) {
    const fs::path dir = freshDir("dicom");
    const auto cta = vv::test::makeSyntheticCta({64, 64, 48}, 3);
    const std::string series = vv::test::writeCtSeries(dir / "series", cta.volume);
    const std::vector<std::string> dicomOptions{"--series", series,        "--threshold",
                                                "200:700",  "--triangles", "20000"};
    // A landmark on the root vessel, halfway along its built centreline.
    const auto& root = cta.tree.segments.front().centerline;
    const glm::vec3 mid = root[root.size() / 2];
    std::vector<std::string> args{"centerline",
                                  (dir / "series").string(),
                                  "-o",
                                  (dir / "c.vtp").string(),
                                  "--json",
                                  "--landmark",
                                  "free:Mid root=" + shortestText(mid.x) + "," +
                                      shortestText(mid.y) + "," + shortestText(mid.z)};
    args.insert(args.end(), dicomOptions.begin(), dicomOptions.end());
    const RunResult centreline = cli(args);
    ASSERT_EQ(centreline.code, 0) << centreline.err;
    std::ofstream(dir / "m.json") << centreline.out;
    std::size_t files = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir / "series")) {
        ++files;
    }
    for (const bool anonymise : {false, true}) {
        const fs::path sr = dir / (anonymise ? "sr-anonymous.dcm" : "sr.dcm");
        std::vector<std::string> report{"report",
                                        (dir / "series").string(),
                                        "-o",
                                        (dir / "r.pdf").string(),
                                        "--size",
                                        "320x240",
                                        "--vss",
                                        "off",
                                        "--measurements",
                                        (dir / "m.json").string(),
                                        "--dicom-sr",
                                        sr.string()};
        report.insert(report.end(), dicomOptions.begin(), dicomOptions.end());
        if (anonymise) {
            report.emplace_back("--anonymise");
        }
        const RunResult r = cli(report);
        ASSERT_EQ(r.code, 0) << r.err;
        if (!anonymise) {
            // The image series under the measurements: the reformation along
            // the file's path and the landmark's section over the volume,
            // drawn by the command line as the GUI draws them.
            std::string text;
            ASSERT_EQ(runTool("pdftotext -layout '" + (dir / "r.pdf").string() + "' -", text), 0);
            text = withoutLigatures(text);
            EXPECT_NE(text.find("Diameter profile along the path"), std::string::npos) << text;
            EXPECT_NE(text.find("Curved reformation along the path"), std::string::npos) << text;
            EXPECT_NE(text.find("Mid root"), std::string::npos) << text;
            int contour = 0;
            int grey = 0;
            for (const QImage& page : pdfPages(dir / "r.pdf", dir / "pages", 100)) {
                for (int y = 0; y < page.height(); ++y) {
                    for (int x = 0; x < page.width(); ++x) {
                        const QColor c = page.pixelColor(x, y);
                        contour += std::abs(c.red() - 230) + std::abs(c.green() - 170) +
                                               std::abs(c.blue()) <
                                           60
                                       ? 1
                                       : 0;
                        // The volume's dark tissue: grey, well below the page's white.
                        grey +=
                            c.red() == c.green() && c.green() == c.blue() && c.red() < 90 ? 1 : 0;
                    }
                }
            }
            EXPECT_GT(contour, 50) << "the section's contour";
            EXPECT_GT(grey, 5000) << "the volume under the reformation and the section";
        }
        std::string dump;
        runTool("dciodvfy '" + sr.string() + "'", dump);
        EXPECT_EQ(dump.find("Error"), std::string::npos) << dump;
        ASSERT_EQ(runTool("dcmdump '" + sr.string() + "'", dump), 0) << dump;
        std::size_t references = 0;
        for (auto at = dump.find("ReferencedSOPInstanceUID"); at != std::string::npos;
             at = dump.find("ReferencedSOPInstanceUID", at + 1)) {
            ++references;
        }
        EXPECT_EQ(references, files) << "every instance of the source series";
        EXPECT_EQ(dump.find(series) == std::string::npos, anonymise)
            << "the source series by its UID, or by a pseudonym when anonymised";
        EXPECT_EQ(dump.find(vv::test::kPatientId) == std::string::npos, anonymise);
    }
}

TEST(ReportMeasurements, WithoutMeasurementsOrWithABadFileNothingIsWritten) {
    const fs::path dir = freshDir("bad");
    vv::demo::AneurysmPhantomOptions o;
    o.targetTriangles = 2'000;
    const fs::path mesh = dir / "a.vtp";
    vv::meshio::writeVtp(vv::demo::makeAneurysmPhantom(o).mesh, mesh);
    EXPECT_EQ(cli({"report", mesh.string(), "-o", (dir / "r.pdf").string(), "--dicom-sr",
                   (dir / "sr.dcm").string()})
                  .code,
              vv::cli::kUsage);
    std::ofstream(dir / "bad.json") << R"({"format": "something else"})";
    const RunResult r =
        cli({"report", mesh.string(), "-o", (dir / "r.pdf").string(), "--measurements",
             (dir / "bad.json").string(), "--dicom-sr", (dir / "sr.dcm").string()});
    EXPECT_NE(r.code, 0);
    EXPECT_NE(r.err.find("bad.json"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "r.pdf"));
    EXPECT_FALSE(fs::exists(dir / "sr.dcm"));
}

}  // namespace

}  // namespace report_measurements_test
