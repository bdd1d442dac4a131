// SPDX-License-Identifier: GPL-3.0-or-later
// `vesselview-cli report` on a DICOM image series (issue 30, item 4): the PDF
// has a "Segmentation" section saying how the vessels were segmented, and
// when a bright tube continues past the segmentation's end (the MR phantom
// whose signal fades towards the head, segmented without the intensity
// correction) it says that the vessel may be cut off, in English and German;
// with the correction (and on CT) it does not. Run as a user runs it (the
// build tree's translations), under `xvfb-run -a`; pdftotext (poppler-utils).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "ReportTestUtil.h"
#include "SyntheticCta.h"
#include "vv/demo/VesselPhantom.h"
#include "vv/dicom/SeriesWriter.h"

namespace {

namespace fs = std::filesystem;
using vv::report::test::runTool;

const fs::path& scratch() {
    static const fs::path dir = [] {
        const fs::path d =
            fs::path(VV_TEST_TMP) / "report-segmentation" / ("run-" + std::to_string(::getpid()));
        fs::remove_all(d);
        fs::create_directories(d);
        return d;
    }();
    return dir;
}

/// The MR vessel phantom with its receive gain 0.3-1.0, written once.
const fs::path& mrSeries() {
    static const fs::path dir = [] {
        vv::demo::VesselPhantomOptions phantom;
        phantom.minGain = 0.3;
        vv::dicom::CtSeriesWriteOptions o;
        o.modality = "MR";
        o.seriesDescription = "phantom MRA";
        const fs::path d = scratch() / "mr";
        (void)vv::dicom::writeCtSeries(d, vv::demo::generateVesselPhantom(phantom).volume, o);
        return d;
    }();
    return dir;
}

/// The report's text (pdftotext, lines joined: a sentence may wrap) of
/// `report SERIES -o PDF OPTIONS`, and what the command printed in
/// `console` (stdout and stderr) when given; fails the test when the command
/// fails.
std::string reportText(const fs::path& series, const std::string& name, const std::string& options,
                       std::string* console = nullptr) {
    const fs::path pdf = scratch() / (name + ".pdf");
    std::string output;
    EXPECT_EQ(runTool("'" + std::string(VV_CLI_EXE) + "' report '" + series.string() + "' -o '" +
                          pdf.string() + "' " + options,
                      output),
              0)
        << output;
    if (console != nullptr) {
        *console = output;
    }
    std::string text;
    EXPECT_EQ(runTool("pdftotext '" + pdf.string() + "' -", text), 0) << text;
    for (char& c : text) {
        c = c == '\n' ? ' ' : c;  // one line: a sentence may wrap
    }
    return vv::report::test::withoutLigatures(text);  // "cut oﬀ" -> "cut off"
}

TEST(ReportSegmentation, TheReportSaysWhenTheVesselMayBeCutOff) {
    std::string console;
    const std::string cut =
        reportText(mrSeries(), "uncorrected-en", "--intensity-correction off --lang en", &console);
    // Said on the console too, as render and segment say it.
    EXPECT_NE(console.find("warning: a bright tube continues"), std::string::npos) << console;
    EXPECT_NE(console.find("--intensity-correction on"), std::string::npos) << console;
    EXPECT_NE(cut.find("Segmentation"), std::string::npos) << cut;
    EXPECT_NE(cut.find("The vessel may be cut off"), std::string::npos) << cut;
    EXPECT_NE(cut.find("towards the head"), std::string::npos) << cut;
    EXPECT_NE(cut.find("Intensity correction"), std::string::npos) << cut;

    const std::string german =
        reportText(mrSeries(), "uncorrected-de", "--intensity-correction off --lang de");
    EXPECT_NE(german.find("Segmentierung"), std::string::npos) << german;
    EXPECT_NE(german.find("möglicherweise abgeschnitten"), std::string::npos) << german;
    EXPECT_EQ(german.find("may be cut off"), std::string::npos) << german;

    // Corrected (the MR default) the whole vessel is segmented: no warning.
    const std::string corrected = reportText(mrSeries(), "corrected-en", "--lang en", &console);
    EXPECT_EQ(console.find("warning"), std::string::npos) << console;
    EXPECT_NE(corrected.find("Segmentation"), std::string::npos) << corrected;
    EXPECT_EQ(corrected.find("cut off"), std::string::npos) << corrected;
    const std::string correctedDe = reportText(mrSeries(), "corrected-de", "--lang de");
    EXPECT_EQ(correctedDe.find("abgeschnitten"), std::string::npos) << correctedDe;

    // CT: the settings without the MR correction, no warning.
    const fs::path ct = scratch() / "ct";
    (void)vv::dicom::writeCtSeries(ct, vv::test::makeSyntheticCta().volume);
    const std::string cta = reportText(ct, "ct-en", "--lang en");
    EXPECT_NE(cta.find("CT angiography default"), std::string::npos) << cta;
    EXPECT_EQ(cta.find("Intensity correction"), std::string::npos) << cta;
    EXPECT_EQ(cta.find("cut off"), std::string::npos) << cta;
}

}  // namespace
