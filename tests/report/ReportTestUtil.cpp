// SPDX-License-Identifier: GPL-3.0-or-later
#include "ReportTestUtil.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <QGuiApplication>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <set>

#include "vv/core/Error.h"

namespace vv::report::test {

void ensureGuiApplication() {
    if (QGuiApplication::instance() == nullptr) {
        if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM") &&
            qEnvironmentVariableIsEmpty("DISPLAY") &&
            qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY")) {
            qputenv("QT_QPA_PLATFORM", "offscreen");
        }
        static int argc = 1;
        static char name[] = "vv_report_tests";
        static char* argv[] = {name, nullptr};
        new QGuiApplication(argc, argv);  // kept for the whole process
    }
}

std::unique_ptr<render::OffscreenRenderer> makeRenderer() {
    try {
        return std::make_unique<render::OffscreenRenderer>();
    } catch (const Error& e) {
        ADD_FAILURE() << "no OpenGL (run under xvfb-run -a, QT_QPA_PLATFORM=xcb): " << e.what();
        return nullptr;
    }
}

std::filesystem::path testDir(const std::string& name) {
    const std::filesystem::path dir =
        std::filesystem::path(VV_TEST_TMP) / "report" / (name + "-" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

scene::Mesh makeTube(const std::string& name) {
    constexpr int kSegments = 32;
    constexpr int kRings = 40;
    scene::Mesh mesh;
    mesh.name = name;
    scene::DataArray wss{.name = "wss",
                         .unit = "Pa",
                         .components = 1,
                         .values = {},
                         .integer = false,
                         .fromCells = false};
    for (int i = 0; i <= kRings; ++i) {
        for (int j = 0; j < kSegments; ++j) {
            const double phi = 2.0 * std::numbers::pi * j / kSegments;
            const float x = 20.0F * static_cast<float>(i) / kRings;
            mesh.positions.emplace_back(x, std::cos(phi), std::sin(phi));
            wss.values.push_back(x * 0.5F);
        }
    }
    for (int i = 0; i < kRings; ++i) {
        for (int j = 0; j < kSegments; ++j) {
            const auto a = static_cast<std::uint32_t>(i * kSegments + j);
            const auto b = static_cast<std::uint32_t>(i * kSegments + (j + 1) % kSegments);
            mesh.indices.insert(mesh.indices.end(),
                                {a, a + kSegments, b, b, a + kSegments, b + kSegments});
        }
    }
    mesh.pointArrays.push_back(std::move(wss));
    scene::computeNormals(mesh);
    return mesh;
}

QImage testImage(int width, int height) {
    QImage image(width, height, QImage::Format_RGB32);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            image.setPixel(
                x, y,
                qRgb(x * 255 / std::max(1, width - 1), y * 255 / std::max(1, height - 1), 128));
        }
    }
    return image;
}

int runTool(const std::string& command, std::string& output) {
    output.clear();
    FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
    if (pipe == nullptr) {
        return -1;
    }
    std::array<char, 4096> buffer{};
    while (std::fgets(buffer.data(), static_cast<int>(buffer.size()), pipe) != nullptr) {
        output += buffer.data();
    }
    const int status = ::pclose(pipe);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

bool haveTool(const std::string& tool) {
    std::string ignored;
    return runTool("command -v " + tool, ignored) == 0;
}

std::string listing(const std::filesystem::path& dir) {
    std::set<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        names.insert(entry.path().filename().string());
    }
    std::string text;
    for (const auto& n : names) {
        text += n + " ";
    }
    return text;
}

}  // namespace vv::report::test
