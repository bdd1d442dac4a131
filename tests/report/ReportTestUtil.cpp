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

#include "TestMeshes.h"
#include "vv/core/Error.h"

namespace vv::report::test {

std::filesystem::path testDir(const std::string& name) {
    const std::filesystem::path dir =
        std::filesystem::path(VV_TEST_TMP) / "report" / (name + "-" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

scene::Mesh makeTube(const std::string& name) {
    scene::Mesh mesh = vv::test::tube(
        {.radius = 1.0F, .start = glm::vec3(0.0F), .length = 20.0F, .segments = 32, .rings = 40});
    mesh.name = name;
    vv::test::addAxialArray(mesh, "wss", "Pa", 0.0F, [](float x) { return 0.5F * x; });
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
