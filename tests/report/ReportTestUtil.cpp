// SPDX-License-Identifier: GPL-3.0-or-later
#include "ReportTestUtil.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <QGuiApplication>
#include <QRectF>
#include <QString>
#include <QTextDocumentFragment>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <regex>
#include <set>
#include <sstream>

#include "RunTool.h"
#include "TestMeshes.h"
#include "vv/core/Error.h"
#include "vv/render/LegendPainter.h"
#include "vv/report/ViewExport.h"

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
    return vv::test::runTool(command, output);
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

std::string withoutLigatures(const std::string& text) {
    return QString::fromStdString(text).normalized(QString::NormalizationForm_KC).toStdString();
}

std::vector<PdfWord> pdfWords(const std::filesystem::path& pdf) {
    std::string html;
    EXPECT_EQ(runTool("pdftotext -bbox '" + pdf.string() + "' -", html), 0)
        << "pdftotext (poppler-utils; scripts/setup-deps): " << html;
    std::vector<PdfWord> all;
    int page = 0;
    const std::regex token(
        R"re(<page |<word xMin="([^"]*)" yMin="([^"]*)" xMax="([^"]*)" yMax="([^"]*)">([^<]*)</word>)re");
    for (auto it = std::sregex_iterator(html.begin(), html.end(), token);
         it != std::sregex_iterator(); ++it) {
        const std::smatch& m = *it;
        if (m.str(0) == "<page ") {
            ++page;
            continue;
        }
        const QString text =
            QTextDocumentFragment::fromHtml(QString::fromStdString(m.str(5))).toPlainText();
        all.push_back({page, std::stod(m.str(1)), std::stod(m.str(2)), std::stod(m.str(3)),
                       std::stod(m.str(4)), text.toStdString()});
    }
    return all;
}

std::vector<std::string> namedViews() {
    std::vector<std::string> names;
    std::stringstream list(render::namedViewNames());
    for (std::string name; std::getline(list, name, ',');) {
        const auto first = name.find_first_not_of(' ');
        names.push_back(name.substr(first, name.find_last_not_of(' ') - first + 1));
    }
    return names;
}

std::pair<double, double> ownDepthRange(render::OffscreenRenderer& renderer,
                                        const scene::Scene& scene,
                                        const render::OffscreenOptions& base,
                                        const render::NamedView& view, const vss::DepthRange& range,
                                        PaperSize paper) {
    ViewExportOptions options;
    options.render = base;
    options.render.width = reportImageWidth(paper);
    options.render.height = static_cast<int>(
        std::lround(options.render.width * static_cast<double>(base.height) / base.width));
    options.render.camera = render::presetCamera(scene, options.render.width, options.render.height,
                                                 view.preset, view.rotation);
    options.render.display.vss.range = range;
    options.legends = false;
    const RenderedView rendered = renderView(renderer, scene, options);
    EXPECT_TRUE(rendered.vss.shown);
    return {rendered.vss.dmin, rendered.vss.dmax};
}

std::string depthLegendProblem(const std::vector<PdfWord>& words, const std::string& heading,
                               const std::string& caption, const render::DepthLegend& legend) {
    const auto top = std::find_if(words.begin(), words.end(),
                                  [&](const PdfWord& w) { return w.text == heading; });
    if (top == words.end()) {
        return "no heading '" + heading + "'";
    }
    std::set<std::string> labels;
    for (const render::LegendTick& tick : render::depthLegendTicks(legend)) {
        labels.insert(tick.label.toStdString());
    }
    const std::string last = render::depthLegendTicks(legend).back().label.toStdString();
    const std::regex number(R"(-?[0-9]+([.,][0-9]+)?)");
    std::vector<std::string> shown;
    std::string text;
    for (auto w = top + 1; w != words.end() && w->page == top->page; ++w) {
        if (w->text == caption && w->top > top->bottom) {
            break;
        }
        text += w->text + " ";
        if (std::regex_match(w->text, number)) {
            shown.push_back(w->text);
        }
    }
    const std::string title = render::depthLegendTitle(legend);
    if (text.find(title) == std::string::npos) {
        return "the legend is not titled '" + title + "': " + text;
    }
    std::string all;
    for (const std::string& n : shown) {
        all += n + " ";
    }
    std::string expected;
    for (const std::string& n : labels) {
        expected += n + " ";
    }
    if (std::find(shown.begin(), shown.end(), last) == shown.end()) {
        return "the legend shows '" + all + "', not the far end " + last + " (ticks " + expected +
               ")";
    }
    for (const std::string& n : shown) {
        if (!labels.contains(n)) {
            return "the legend shows " + n + ", no tick of its view's range (ticks " + expected +
                   "; shown " + all + ")";
        }
    }
    return {};
}

std::vector<QImage> pdfPages(const std::filesystem::path& pdf, const std::filesystem::path& dir,
                             int dpi) {
    std::filesystem::create_directories(dir);
    std::string output;
    EXPECT_EQ(runTool("pdftoppm -r " + std::to_string(dpi) + " -png '" + pdf.string() + "' '" +
                          (dir / "page").string() + "'",
                      output),
              0)
        << "pdftoppm (poppler-utils; scripts/setup-deps): " << output;
    // pdftoppm numbers the pages with as many digits as the last needs.
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        const std::string name = entry.path().filename().string();
        if (name.rfind("page-", 0) == 0 && entry.path().extension() == ".png") {
            files.push_back(entry.path());
        }
    }
    std::sort(files.begin(), files.end(), [](const auto& a, const auto& b) {
        const auto number = [](const std::filesystem::path& p) {
            return std::stoi(p.stem().string().substr(5));
        };
        return number(a) < number(b);
    });
    std::vector<QImage> pages;
    for (const auto& file : files) {
        pages.emplace_back(QString::fromStdString(file.string()));
        EXPECT_FALSE(pages.back().isNull()) << file;
    }
    EXPECT_FALSE(pages.empty()) << pdf;
    return pages;
}

std::vector<std::string> marginProblems(const QImage& page, int dpi) {
    const auto px = [dpi](double mm) { return mm / 25.4 * dpi; };
    const QImage image = page.convertToFormat(QImage::Format_RGB32);
    const double w = image.width();
    const double h = image.height();
    // One pixel of anti-aliasing on each boundary.
    const QRectF content(px(18.0) - 1.0, px(15.0) - 1.0, w - 2.0 * px(18.0) + 2.0,
                         h - px(15.0) - px(15.0) + 2.0);
    const QRectF gap(0.0, h - px(15.0) - px(9.0) + 1.0, w, px(3.0) - 2.0);
    std::vector<std::string> problems;
    int outside = 0;
    int inGap = 0;
    QPoint firstOutside;
    QPoint firstInGap;
    for (int y = 0; y < image.height(); ++y) {
        const auto* row = reinterpret_cast<const QRgb*>(image.constScanLine(y));
        for (int x = 0; x < image.width(); ++x) {
            if (qRed(row[x]) >= 250 && qGreen(row[x]) >= 250 && qBlue(row[x]) >= 250) {
                continue;
            }
            const QPointF centre(x + 0.5, y + 0.5);
            if (!content.contains(centre)) {
                firstOutside = outside++ == 0 ? QPoint(x, y) : firstOutside;
            } else if (gap.contains(centre)) {
                firstInGap = inGap++ == 0 ? QPoint(x, y) : firstInGap;
            }
        }
    }
    if (outside > 0) {
        problems.push_back(
            std::to_string(outside) + " pixels of ink outside the margins, first at (" +
            std::to_string(firstOutside.x()) + ", " + std::to_string(firstOutside.y()) + ")");
    }
    if (inGap > 0) {
        problems.push_back(std::to_string(inGap) +
                           " pixels of ink between the content and the footer, first at (" +
                           std::to_string(firstInGap.x()) + ", " + std::to_string(firstInGap.y()) +
                           ")");
    }
    return problems;
}

}  // namespace vv::report::test
