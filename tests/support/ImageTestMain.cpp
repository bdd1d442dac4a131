// SPDX-License-Identifier: GPL-3.0-or-later
// vv_image_test: one image baseline test (cmake/VVImageTests.cmake declares them).
//
//   vv_image_test --name NAME --cli VESSELVIEW_CLI --baseline BASELINE.png
//                 --out-dir DIR --threshold T -- RENDER_ARGS...
//
// Runs `VESSELVIEW_CLI render RENDER_ARGS -o DIR/NAME.render.png`, compares the
// image with BASELINE.png (ImageCompare.h) and passes when the difference is
// at most T. Otherwise (or without a baseline) the candidate is kept as
// DIR/NAME.png, a picture of the differences as DIR/NAME.diff.png, both paths
// are printed and the test fails.
//
// With VV_UPDATE_BASELINES set to anything but "" or "0", the candidate is
// copied over BASELINE.png instead (for a person to look at and commit) and
// the test passes.
//
// Exit codes: 0 pass (or updated), 1 mismatch or missing baseline, 2 usage,
// 3 the render failed.
#include <QCoreApplication>
#include <QFile>
#include <QImage>
#include <QProcess>
#include <QString>
#include <QStringList>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>
#include <system_error>
#include <vector>

#include "ImageCompare.h"

namespace {

namespace fs = std::filesystem;

struct Arguments {
    std::string name;
    std::string cli;
    fs::path baseline;
    fs::path outDir;
    double threshold = -1.0;
    QStringList renderArgs;
};

bool parse(int argc, char** argv, Arguments& a) {
    int i = 1;
    for (; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--") {
            ++i;
            break;
        }
        if (i + 1 >= argc) {
            std::cerr << "vv_image_test: " << arg << " needs a value\n";
            return false;
        }
        const std::string value = argv[++i];
        if (arg == "--name") {
            a.name = value;
        } else if (arg == "--cli") {
            a.cli = value;
        } else if (arg == "--baseline") {
            a.baseline = value;
        } else if (arg == "--out-dir") {
            a.outDir = value;
        } else if (arg == "--threshold") {
            const auto [ptr, ec] =
                std::from_chars(value.data(), value.data() + value.size(), a.threshold);
            if (ec != std::errc() || ptr != value.data() + value.size() || !(a.threshold >= 0.0)) {
                std::cerr << "vv_image_test: bad --threshold '" << value << "'\n";
                return false;
            }
        } else {
            std::cerr << "vv_image_test: unknown option " << arg << "\n";
            return false;
        }
    }
    for (; i < argc; ++i) {
        a.renderArgs << QString::fromLocal8Bit(argv[i]);
    }
    if (a.name.empty() || a.cli.empty() || a.baseline.empty() || a.outDir.empty() ||
        a.threshold < 0.0 || a.renderArgs.isEmpty()) {
        std::cerr << "usage: vv_image_test --name NAME --cli EXE --baseline PNG --out-dir DIR "
                     "--threshold T -- RENDER_ARGS...\n";
        return false;
    }
    return true;
}

bool updateMode() {
    const QByteArray value = qgetenv("VV_UPDATE_BASELINES");
    return !value.isEmpty() && value != "0";
}

QString qpath(const fs::path& p) {
    return QFile::decodeName(p.c_str());
}

}  // namespace

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);
    Arguments a;
    if (!parse(argc, argv, a)) {
        return 2;
    }
    std::error_code ec;
    fs::create_directories(a.outDir, ec);
    const fs::path rendered = a.outDir / (a.name + ".render.png");
    const fs::path candidate = a.outDir / (a.name + ".png");
    const fs::path diff = a.outDir / (a.name + ".diff.png");
    fs::remove(rendered, ec);
    fs::remove(candidate, ec);
    fs::remove(diff, ec);

    QProcess render;
    render.setProcessChannelMode(QProcess::ForwardedChannels);
    QStringList args;
    args << QStringLiteral("render") << a.renderArgs << QStringLiteral("-o") << qpath(rendered);
    std::cout << "render: " << a.cli << " " << args.join(' ').toStdString() << std::endl;
    render.start(QString::fromStdString(a.cli), args);
    if (!render.waitForFinished(240000) || render.exitStatus() != QProcess::NormalExit ||
        render.exitCode() != 0) {
        std::cout << "FAIL " << a.name << ": the render failed (exit code " << render.exitCode()
                  << ", " << render.errorString().toStdString() << ")" << std::endl;
        return 3;
    }
    const QImage image(qpath(rendered));
    if (image.isNull()) {
        std::cout << "FAIL " << a.name << ": cannot read the rendered image " << rendered.string()
                  << std::endl;
        return 3;
    }

    const bool haveBaseline = fs::exists(a.baseline, ec);
    const QImage baseline = haveBaseline ? QImage(qpath(a.baseline)) : QImage();
    vv::test::ImageComparison comparison;
    if (haveBaseline) {
        comparison = vv::test::compareImages(image, baseline);
    }

    if (updateMode()) {
        fs::create_directories(a.baseline.parent_path(), ec);
        fs::copy_file(rendered, a.baseline, fs::copy_options::overwrite_existing, ec);
        if (ec) {
            std::cout << "FAIL " << a.name << ": cannot write " << a.baseline.string() << ": "
                      << ec.message() << std::endl;
            return 1;
        }
        fs::remove(rendered, ec);
        std::cout << "UPDATED " << a.baseline.string() << " ("
                  << (haveBaseline ? "was: " + comparison.message : std::string("new baseline"))
                  << "); look at it before committing" << std::endl;
        return 0;
    }

    if (!haveBaseline || baseline.isNull()) {
        fs::rename(rendered, candidate, ec);
        std::cout << "FAIL " << a.name << ": "
                  << (haveBaseline ? "cannot read the baseline " : "no baseline ")
                  << a.baseline.string() << "\n  candidate: " << candidate.string()
                  << "\n  (VV_UPDATE_BASELINES=1 ctest -L baseline, or scripts/update-baselines,"
                     " writes the candidates into tests/baselines/)"
                  << std::endl;
        return 1;
    }
    char threshold[32];
    std::snprintf(threshold, sizeof threshold, "%.4f", a.threshold);
    if (!comparison.comparable || !(comparison.difference <= a.threshold)) {
        fs::rename(rendered, candidate, ec);
        std::cout << "FAIL " << a.name << ": " << comparison.message << " > threshold " << threshold
                  << "\n  baseline:  " << a.baseline.string()
                  << "\n  candidate: " << candidate.string();
        const QImage picture = vv::test::differenceImage(image, baseline);
        if (!picture.isNull() && picture.save(qpath(diff), "PNG")) {
            std::cout << "\n  differences (x4): " << diff.string();
        }
        std::cout << std::endl;
        return 1;
    }
    fs::remove(rendered, ec);
    std::cout << "PASS " << a.name << ": " << comparison.message << " <= threshold " << threshold
              << std::endl;
    return 0;
}
