// SPDX-License-Identifier: GPL-3.0-or-later
// The real-world corpus: every file pydicom ships for its own tests (Debian's
// python3-pydicom). Each one loads, or is refused / skipped with a message
// naming it; none crashes or hangs (ctest TIMEOUT). Decoded values are
// compared with pydicom's own pixel arrays (tests/dicom/dicom_pixels.py) for the
// files both can decode.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "vv/core/Error.h"
#include "vv/dicom/Dicom.h"

namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

const fs::path kCorpus = "/usr/lib/python3/dist-packages/pydicom/data/test_files";

std::vector<fs::path> corpusFiles() {
    std::vector<fs::path> files;
    for (const auto& e : fs::recursive_directory_iterator(kCorpus)) {
        if (e.is_regular_file()) {
            files.push_back(e.path());
        }
    }
    std::sort(files.begin(), files.end());
    return files;
}

enum class Outcome { Loaded, Refused, Skipped };

struct FileResult {
    Outcome outcome = Outcome::Skipped;
    std::string message;
};

/// Scans `file` and loads every series it yields; never lets a non-vv
/// exception through silently.
FileResult tryFile(const fs::path& file) {
    FileResult r;
    vv::dicom::DicomScanResult scan;
    try {
        scan = vv::dicom::scanDicom(file);
    } catch (const std::exception& e) {
        ADD_FAILURE() << file << ": scanDicom threw " << e.what();
        r.outcome = Outcome::Refused;
        return r;
    }
    const auto series = scan.allSeries();
    if (series.empty()) {
        EXPECT_FALSE(scan.skipped.empty()) << file << ": no series and nothing skipped";
        if (!scan.skipped.empty()) {
            EXPECT_FALSE(scan.skipped.front().reason.empty()) << file;
            r.message = scan.skipped.front().reason;
            // The entry names the file (or, for a DICOMDIR, the files it lists).
            EXPECT_TRUE(std::any_of(scan.skipped.begin(), scan.skipped.end(), [&](const auto& k) {
                return !k.file.empty();
            })) << file;
            EXPECT_TRUE(scan.skipped.front().file == file || scan.skipped.size() > 1 ||
                        scan.filesExamined > 1)
                << file << " vs " << scan.skipped.front().file;
        }
        r.outcome = Outcome::Skipped;
        return r;
    }
    r.outcome = Outcome::Loaded;
    for (const auto* s : series) {
        try {
            const auto v = vv::dicom::loadDicomSeries(*s);
            EXPECT_FALSE(v.volume.empty()) << file;
        } catch (const vv::Error& e) {
            r.outcome = Outcome::Refused;
            r.message = e.what();
            // The message names a file of the series.
            const bool named =
                std::any_of(s->files.begin(), s->files.end(), [&](const fs::path& f) {
                    return r.message.find(f.filename().string()) != std::string::npos;
                });
            EXPECT_TRUE(named) << file << ": message names no file: " << r.message;
        } catch (const std::exception& e) {
            ADD_FAILURE() << file << ": not a vv::Error: " << e.what();
            r.outcome = Outcome::Refused;
        }
    }
    return r;
}

TEST(DicomCorpus, EveryFileLoadsOrIsRefusedWithAClearMessage) {
    if (!fs::is_directory(kCorpus)) {
        GTEST_SKIP() << "python3-pydicom's test files are not installed (scripts/setup-deps)";
    }
    const auto files = corpusFiles();
    ASSERT_GT(files.size(), 50U);
    std::map<std::string, FileResult> results;
    int loaded = 0;
    int refused = 0;
    int skipped = 0;
    for (const auto& f : files) {
        const FileResult r = tryFile(f);
        (r.outcome == Outcome::Loaded    ? loaded
         : r.outcome == Outcome::Refused ? refused
                                         : skipped)++;
        const std::string rel = fs::relative(f, kCorpus).string();
        std::printf("  %-8s %-60s %s\n",
                    r.outcome == Outcome::Loaded    ? "loaded"
                    : r.outcome == Outcome::Refused ? "refused"
                                                    : "skipped",
                    rel.c_str(), r.message.substr(0, 160).c_str());
        results[rel] = r;
    }
    std::printf("corpus: %zu files: %d loaded, %d refused, %d skipped\n", files.size(), loaded,
                refused, skipped);
    RecordProperty("loaded", loaded);
    RecordProperty("refused", refused);
    RecordProperty("skipped", skipped);

    const auto expectOutcome = [&](const std::string& rel, Outcome o,
                                   const std::string& text = {}) {
        const auto it = results.find(rel);
        if (it == results.end()) {
            return;  // not shipped by this pydicom version
        }
        EXPECT_EQ(static_cast<int>(it->second.outcome), static_cast<int>(o))
            << rel << ": " << it->second.message;
        if (!text.empty()) {
            EXPECT_THAT(it->second.message, HasSubstr(text)) << rel;
        }
    };
    // Every transfer syntax DCMTK decodes.
    for (const char* ok :
         {"CT_small.dcm", "MR_small.dcm", "MR_small_implicit.dcm", "MR_small_bigendian.dcm",
          "MR_small_expb.dcm", "MR_small_RLE.dcm", "MR_small_jpeg_ls_lossless.dcm",
          "MR_small_padded.dcm", "JPEG-lossy.dcm", "JPGExtended.dcm", "image_dfl.dcm", "rtdose.dcm",
          "rtdose_expb.dcm", "rtdose_rle.dcm", "liver_1frame.dcm", "liver_expb_1frame.dcm"}) {
        expectOutcome(ok, Outcome::Loaded);
    }
    for (const char* j2k : {"JPEG2000.dcm", "MR_small_jp2klossless.dcm", "693_J2KI.dcm",
                            "J2K_pixelrep_mismatch.dcm"}) {
        expectOutcome(j2k, Outcome::Refused, "JPEG 2000 is not supported (DCMTK has no decoder)");
    }
    expectOutcome("MR_truncated.dcm", Outcome::Refused, "truncated");
    expectOutcome("SC_rgb_rle.dcm", Outcome::Refused, "colour");
    expectOutcome("test-SR.dcm", Outcome::Skipped, "structured report");
    expectOutcome("rtplan.dcm", Outcome::Skipped, "RT plan");
    expectOutcome("rtstruct.dcm", Outcome::Skipped, "RT structure set");
    expectOutcome("waveform_ecg.dcm", Outcome::Skipped, "waveform");
    expectOutcome("README.txt", Outcome::Skipped, "not a DICOM file");
    EXPECT_GE(loaded, 40);
}

TEST(DicomCorpus, DicomdirIsFollowed) {
    const fs::path dicomdir = kCorpus / "dicomdirtests" / "DICOMDIR";
    if (!fs::exists(dicomdir)) {
        GTEST_SKIP() << "no DICOMDIR in the corpus";
    }
    const auto scan = vv::dicom::scanDicom(dicomdir);
    EXPECT_GE(scan.allSeries().size(), 5U);
    std::size_t images = 0;
    for (const auto* s : scan.allSeries()) {
        images += s->imageCount;
        EXPECT_FALSE(s->seriesInstanceUid.empty());
    }
    EXPECT_GE(images, 20U);
    // The same folder walked directly finds the same images, and skips the
    // DICOMDIR files themselves.
    const auto walked = vv::dicom::scanDicom(kCorpus / "dicomdirtests");
    std::size_t walkedImages = 0;
    for (const auto* s : walked.allSeries()) {
        walkedImages += s->imageCount;
    }
    EXPECT_GE(walkedImages, images);
    EXPECT_TRUE(std::any_of(walked.skipped.begin(), walked.skipped.end(), [](const auto& s) {
        return s.reason.find("DICOMDIR") != std::string::npos;
    }));
}

// ---------------------------------------------------------------------------

std::string shellQuote(const std::string& s) {
    std::string out = "'";
    for (const char c : s) {
        if (c == '\'') {
            out += "'\\''";
        } else {
            out += c;
        }
    }
    return out + "'";
}

/// A python3 that imports pydicom and numpy, or empty.
std::string findPython() {
    std::vector<std::string> candidates;
    if (const char* env = std::getenv("VV_PYTHON3"); env != nullptr && *env != '\0') {
        candidates.emplace_back(env);
    }
    candidates.emplace_back("/usr/bin/python3");
    candidates.emplace_back("python3");
    for (const auto& c : candidates) {
        const std::string cmd = shellQuote(c) + " -c 'import pydicom, numpy' >/dev/null 2>&1";
        if (std::system(cmd.c_str()) == 0) {
            return c;
        }
    }
    return {};
}

std::vector<float> readFloats(const fs::path& file, std::size_t count) {
    std::vector<float> v(count);
    std::ifstream in(file, std::ios::binary);
    in.read(reinterpret_cast<char*>(v.data()), static_cast<std::streamsize>(count * sizeof(float)));
    if (static_cast<std::size_t>(in.gcount()) != count * sizeof(float)) {
        v.clear();
    }
    return v;
}

/// Largest difference between the volume and pydicom's frames, taking the
/// frames in order or reversed (the volume is in position order).
double compare(const vv::scene::Volume& vol, const std::vector<float>& ref, int frames, int rows,
               int columns) {
    double best = INFINITY;
    for (const bool reversed : {false, true}) {
        double worst = 0;
        for (int f = 0; f < frames && worst < best; ++f) {
            const int k = reversed ? frames - 1 - f : f;
            for (int j = 0; j < rows; ++j) {
                for (int i = 0; i < columns; ++i) {
                    const float r = ref[(static_cast<std::size_t>(f) * rows + j) * columns + i];
                    const double d = std::abs(static_cast<double>(vol.value(i, j, k)) - r);
                    worst = std::max(worst, std::isnan(d) ? INFINITY : d);
                }
            }
        }
        best = std::min(best, worst);
    }
    return best;
}

TEST(DicomCorpus, DecodedValuesMatchPydicom) {
    if (!fs::is_directory(kCorpus)) {
        GTEST_SKIP() << "python3-pydicom's test files are not installed";
    }
    const std::string python = findPython();
    if (python.empty()) {
        GTEST_SKIP() << "no python3 with pydicom and numpy (scripts/setup-deps installs them)";
    }
    const fs::path out = fs::path(VV_TEST_TMP) / "dicom" / "pydicom";
    fs::remove_all(out);
    fs::create_directories(out);
    const auto files = corpusFiles();
    std::string cmd = shellQuote(python) + " " +
                      shellQuote(std::string(VV_SOURCE_DIR) + "/tests/dicom/dicom_pixels.py") +
                      " " + shellQuote(out.string());
    for (const auto& f : files) {
        cmd += " " + shellQuote(f.string());
    }
    ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;

    std::ifstream manifest(out / "manifest.tsv");
    std::string line;
    int both = 0;
    int matched = 0;
    int pydicomOnly = 0;
    int vesselViewOnly = 0;
    while (std::getline(manifest, line)) {
        std::stringstream ss(line);
        std::string index;
        std::string status;
        std::string detail;
        std::string file;
        std::getline(ss, index, '\t');
        std::getline(ss, status, '\t');
        std::getline(ss, detail, '\t');
        std::getline(ss, file);
        bool ours = false;
        vv::dicom::DicomVolume v;
        try {
            v = vv::dicom::loadDicomVolume(file);
            ours = true;
        } catch (const vv::Error&) {
        }
        if (status != "ok") {
            vesselViewOnly += ours ? 1 : 0;
            continue;
        }
        if (!ours) {
            ++pydicomOnly;
            std::printf("  pydicom only: %s\n", file.c_str());
            continue;
        }
        int frames = 0;
        int rows = 0;
        int columns = 0;
        ASSERT_EQ(std::sscanf(detail.c_str(), "%d,%d,%d", &frames, &rows, &columns), 3) << line;
        ++both;
        const bool resampled = std::any_of(v.warnings.begin(), v.warnings.end(), [](const auto& w) {
            return w.kind == vv::dicom::DicomWarning::Kind::NonUniformSpacing ||
                   w.kind == vv::dicom::DicomWarning::Kind::MissingSlices;
        });
        if (resampled || v.volume.dims() != glm::ivec3(columns, rows, frames)) {
            ADD_FAILURE() << file << ": volume " << v.volume.dims().x << "x" << v.volume.dims().y
                          << "x" << v.volume.dims().z << " vs pydicom " << columns << "x" << rows
                          << "x" << frames;
            continue;
        }
        const auto ref =
            readFloats(out / (index + ".raw"), static_cast<std::size_t>(frames) * rows * columns);
        ASSERT_FALSE(ref.empty()) << file;
        // Lossless data must match exactly; lossy JPEG within one unit.
        const auto scan = vv::dicom::scanDicom(file);
        const std::string syntax =
            scan.allSeries().empty() ? std::string() : scan.allSeries()[0]->transferSyntaxUid;
        const bool lossy = syntax == "1.2.840.10008.1.2.4.50" ||
                           syntax == "1.2.840.10008.1.2.4.51" || syntax == "1.2.840.10008.1.2.4.81";
        const double diff = compare(v.volume, ref, frames, rows, columns);
        EXPECT_LE(diff, lossy ? 1.0 : 0.0) << file;
        if (diff <= (lossy ? 1.0 : 0.0)) {
            ++matched;
        }
    }
    std::printf(
        "pydicom comparison: %d decoded by both, %d matched; %d pydicom only, %d VesselView only\n",
        both, matched, pydicomOnly, vesselViewOnly);
    RecordProperty("matched", matched);
    EXPECT_GE(matched, 20);
    EXPECT_EQ(matched, both);
}

/// Files pydicom cannot decode here (no JPEG plugin) against the same image
/// uncompressed, which pydicom can: MR_small in every transfer syntax.
TEST(DicomCorpus, CompressedVariantsEqualTheUncompressedImage) {
    const fs::path reference = kCorpus / "MR_small.dcm";
    if (!fs::exists(reference)) {
        GTEST_SKIP() << "MR_small.dcm not installed";
    }
    const auto ref = vv::dicom::loadDicomVolume(reference);
    for (const char* name :
         {"MR_small_RLE.dcm", "MR_small_jpeg_ls_lossless.dcm", "MR_small_bigendian.dcm",
          "MR_small_expb.dcm", "MR_small_implicit.dcm"}) {
        const fs::path f = kCorpus / name;
        if (!fs::exists(f)) {
            continue;
        }
        const auto v = vv::dicom::loadDicomVolume(f);
        ASSERT_EQ(v.volume.dims(), ref.volume.dims()) << name;
        double worst = 0;
        for (std::size_t n = 0; n < v.volume.voxelCount(); ++n) {
            worst = std::max(
                worst, static_cast<double>(std::abs(v.volume.valueAt(n) - ref.volume.valueAt(n))));
        }
        EXPECT_EQ(worst, 0.0) << name;
    }
}

}  // namespace
