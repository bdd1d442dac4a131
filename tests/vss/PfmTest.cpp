// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

#include "vv/core/Error.h"
#include "vv/vss/Pfm.h"

namespace vv::vss {
namespace {

namespace fs = std::filesystem;

fs::path tempDir() {
    const fs::path dir = fs::path(VV_TEST_TMP) / "vss-pfm";
    fs::create_directories(dir);
    return dir;
}

void writeBytes(const fs::path& file, const std::string& bytes) {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

std::string floatBytes(float v, bool bigEndian) {
    char b[4];
    std::memcpy(b, &v, 4);
    if (bigEndian) {
        std::swap(b[0], b[3]);
        std::swap(b[1], b[2]);
    }
    return std::string(b, 4);
}

TEST(PfmTest, RoundTripKeepsValuesNaNAndInf) {
    Image<float> image(5, 3);
    for (int y = 0; y < 3; ++y) {
        for (int x = 0; x < 5; ++x) {
            image(x, y) = static_cast<float>(x * 10 + y) * 0.37F - 2.0F;
        }
    }
    image(1, 1) = std::numeric_limits<float>::quiet_NaN();
    image(2, 2) = std::numeric_limits<float>::infinity();
    image(3, 0) = -std::numeric_limits<float>::infinity();
    const fs::path file = tempDir() / "round.pfm";
    writePfm(file, image.view());
    // Size: header + data, nothing else.
    const std::string header = "Pf\n5 3\n-1.0\n";
    EXPECT_EQ(fs::file_size(file), header.size() + 5 * 3 * 4);
    const auto back = readPfm(file);
    ASSERT_EQ(back.width(), 5);
    ASSERT_EQ(back.height(), 3);
    for (int y = 0; y < 3; ++y) {
        for (int x = 0; x < 5; ++x) {
            if (std::isnan(image(x, y))) {
                EXPECT_TRUE(std::isnan(back(x, y)));
            } else {
                EXPECT_EQ(back(x, y), image(x, y)) << x << ", " << y;
            }
        }
    }
}

TEST(PfmTest, RowsAreBottomToTopAndBothEndiannessesRead) {
    for (const bool big : {false, true}) {
        // 2x2: file rows bottom first: bottom row (1, 2), top row (3, 4).
        std::string bytes = std::string("Pf\n2 2\n") + (big ? "1.0" : "-1.0") + "\n";
        for (const float v : {1.0F, 2.0F, 3.0F, 4.0F}) {
            bytes += floatBytes(v, big);
        }
        const fs::path file = tempDir() / (big ? "big.pfm" : "little.pfm");
        writeBytes(file, bytes);
        const auto image = readPfm(file);
        EXPECT_EQ(image(0, 0), 3.0F);
        EXPECT_EQ(image(1, 0), 4.0F);
        EXPECT_EQ(image(0, 1), 1.0F);
        EXPECT_EQ(image(1, 1), 2.0F);
    }
}

TEST(PfmTest, WhitespaceVariantsInTheHeader) {
    std::string bytes = "Pf 1\t1   -2.5\n" + floatBytes(7.0F, false);
    const fs::path file = tempDir() / "spaces.pfm";
    writeBytes(file, bytes);
    EXPECT_EQ(readPfm(file)(0, 0), 7.0F);
}

/// Expects FormatError naming the file, with `words` in the message.
void expectFormatError(const std::string& name, const std::string& bytes,
                       const std::string& words) {
    const fs::path file = tempDir() / name;
    writeBytes(file, bytes);
    try {
        static_cast<void>(readPfm(file));
        ADD_FAILURE() << name << ": no error";
    } catch (const FormatError& e) {
        EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
}

TEST(PfmTest, StrictValidation) {
    const std::string pixel = floatBytes(1.0F, false);
    expectFormatError("empty.pfm", "", "not a PFM");
    expectFormatError("magic.pfm", "P5\n1 1\n255\n" + pixel, "not a PFM");
    expectFormatError("colour.pfm", "PF\n1 1\n-1.0\n" + pixel + pixel + pixel, "colour");
    expectFormatError("nospace.pfm", "Pf1 1\n-1.0\n" + pixel, "not a PFM");
    expectFormatError("alpha.pfm", "Pf\nabc 1\n-1.0\n" + pixel, "not a whole number");
    expectFormatError("float-size.pfm", "Pf\n1.5 1\n-1.0\n" + pixel, "not a whole number");
    expectFormatError("negative.pfm", "Pf\n-4 1\n-1.0\n" + pixel, "negative");
    expectFormatError("negative-h.pfm", "Pf\n4 -1\n-1.0\n" + pixel, "negative");
    expectFormatError("zero.pfm", "Pf\n0 1\n-1.0\n", "is 0");
    expectFormatError("huge.pfm", "Pf\n40000 1\n-1.0\n" + pixel, "larger than");
    expectFormatError("huger.pfm", "Pf\n99999999999999999999999 1\n-1.0\n" + pixel, "larger than");
    expectFormatError("many.pfm", "Pf\n30000 30000\n-1.0\n" + pixel, "pixels");
    expectFormatError("scale0.pfm", "Pf\n1 1\n0.0\n" + pixel, "scale");
    expectFormatError("scalenan.pfm", "Pf\n1 1\nnan\n" + pixel, "scale");
    expectFormatError("scaletext.pfm", "Pf\n1 1\nx\n" + pixel, "scale");
    expectFormatError("header-only.pfm", "Pf\n2 2\n-1.0", "no data");
    expectFormatError("short-header.pfm", "Pf\n2", "ends");
    expectFormatError("truncated.pfm", "Pf\n2 2\n-1.0\n" + pixel + pixel + pixel, "truncated");
    expectFormatError("trailing.pfm", "Pf\n1 1\n-1.0\n" + pixel + "xx", "after the pixel data");
}

TEST(PfmTest, IoErrorsNameTheFile) {
    const fs::path missing = tempDir() / "does-not-exist.pfm";
    try {
        static_cast<void>(readPfm(missing));
        ADD_FAILURE() << "no error";
    } catch (const IoError& e) {
        EXPECT_NE(std::string(e.what()).find("does-not-exist.pfm"), std::string::npos);
    }
    EXPECT_THROW(static_cast<void>(readPfm(tempDir())), IoError);
    const Image<float> image(2, 2, 1.0F);
    EXPECT_THROW(writePfm(tempDir() / "no-such-folder" / "x.pfm", image.view()), IoError);
    EXPECT_THROW(writePfm(tempDir() / "empty.pfm", Image<float>().view()), InvalidArgumentError);
}

TEST(PfmTest, WriteIsAtomicOverAnExistingFile) {
    const fs::path dir = tempDir() / "atomic";
    fs::create_directories(dir);
    const fs::path file = dir / "atomic.pfm";
    writePfm(file, Image<float>(3, 3, 1.0F).view());
    writePfm(file, Image<float>(4, 2, 2.0F).view());
    const auto back = readPfm(file);
    EXPECT_EQ(back.width(), 4);
    EXPECT_EQ(back(3, 1), 2.0F);
    for (const auto& entry : fs::directory_iterator(dir)) {
        EXPECT_EQ(entry.path().filename().string().find(".tmp-"), std::string::npos)
            << "temporary left behind: " << entry.path();
    }
}

}  // namespace
}  // namespace vv::vss
