// SPDX-License-Identifier: GPL-3.0-or-later
// Legends in every exported file show the colour map's exact colours: the
// PDF (rasterised with pdftoppm, poppler-utils), the PNG and the DICOM
// Secondary Capture. Each bin / sample of the bar within CIEDE2000 2 of the
// colour map's table (tests/support/ColourDifference.h).
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <gtest/gtest.h>

#include <QImage>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "ColourDifference.h"
#include "ReportTestUtil.h"
#include "vv/render/LegendPainter.h"
#include "vv/report/PdfReport.h"
#include "vv/report/ReportJob.h"

namespace vv::report {
namespace {

namespace fs = std::filesystem;

constexpr int kBins = 6;

std::vector<QRgb> table(const std::vector<glm::u8vec4>& lut) {
    std::vector<QRgb> colours;
    for (const glm::u8vec4& c : lut) {
        colours.push_back(qRgb(c.r, c.g, c.b));
    }
    return colours;
}

std::vector<QRgb> binTable() {
    return table(colormaps::lut(colormaps::ColorMap::Inferno, kBins));
}

std::vector<QRgb> depthTable() {
    return table(colormaps::lut(colormaps::DepthScale::Chromadepth, 256));
}

/// Checks the bar of `colours` inside `area` of `image`; `what` names it.
void expectBar(const QImage& image, const QRect& area, const std::vector<QRgb>& colours, int minRun,
               const std::string& what) {
    SCOPED_TRACE(what);
    const auto bar = vv::test::findBar(image, area, colours.front(), colours.back(), minRun);
    ASSERT_TRUE(bar) << "no bar from (" << qRed(colours.front()) << "," << qGreen(colours.front())
                     << "," << qBlue(colours.front()) << ") to (" << qRed(colours.back()) << ","
                     << qGreen(colours.back()) << "," << qBlue(colours.back())
                     << "): dimmed or blended";
    for (const std::string& line : vv::test::barMismatches(image, *bar, colours)) {
        ADD_FAILURE() << line;
    }
}

/// This process's folder of the test's files.
const fs::path& dir() {
    static const fs::path folder = test::testDir("legend-colours");
    return folder;
}

/// The first page of `pdf` at `dpi` (pdftoppm), written as dir()/name.pdf first.
QImage rasterise(const QByteArray& pdf, const std::string& name, int dpi) {
    const fs::path file = dir() / (name + ".pdf");
    {
        std::ofstream out(file, std::ios::binary);
        out.write(pdf.constData(), pdf.size());
    }
    std::string output;
    const fs::path stem = dir() / name;
    EXPECT_EQ(test::runTool("pdftoppm -png -r " + std::to_string(dpi) + " -f 1 -l 1 -singlefile '" +
                                file.string() + "' '" + stem.string() + "'",
                            output),
              0)
        << "pdftoppm (poppler-utils) missing? run scripts/setup-deps: " << output;
    return QImage(QString::fromStdString(stem.string() + ".png"))
        .convertToFormat(QImage::Format_RGB32);
}

/// The pixels of a DICOM Secondary Capture (RGB, 8 bits, interleaved).
QImage readSecondaryCapture(const fs::path& file) {
    DcmFileFormat format;
    if (format.loadFile(OFFilename(file.c_str())).bad()) {
        return {};
    }
    DcmDataset& data = *format.getDataset();
    Uint16 rows = 0;
    Uint16 columns = 0;
    const Uint8* pixels = nullptr;
    unsigned long count = 0;
    data.findAndGetUint16(DCM_Rows, rows);
    data.findAndGetUint16(DCM_Columns, columns);
    if (data.findAndGetUint8Array(DCM_PixelData, pixels, &count).bad() ||
        count < 3UL * rows * columns) {
        return {};
    }
    QImage image(columns, rows, QImage::Format_RGB32);
    for (int y = 0; y < rows; ++y) {
        for (int x = 0; x < columns; ++x) {
            const Uint8* p = pixels + 3 * (static_cast<std::size_t>(y) * columns + x);
            image.setPixel(x, y, qRgb(p[0], p[1], p[2]));
        }
    }
    return image;
}

TEST(LegendColourTest, PdfLegendsShowTheColourMapsColours) {
    test::ensureGuiApplication();
    ReportContent c;
    const int width = reportImageWidth(PaperSize::A4);
    c.view.image = QImage(width, width * 3 / 4, QImage::Format_RGB32);
    c.view.image.fill(Qt::white);  // nothing in the view looks like a legend colour
    c.view.legends.depth =
        render::DepthLegend{colormaps::DepthScale::Chromadepth, 10.0, 52.0, "mm"};
    c.view.legends.parameter = render::ParameterLegend{
        "wss", "Pa", 0.45F, 1.31F, colormaps::ColorMap::Inferno, kBins, {}, {}};
    const QByteArray pdf = renderPdf(c, PaperSize::A4);
    const QImage page = rasterise(pdf, "report", 150);
    ASSERT_FALSE(page.isNull());
    expectBar(page, page.rect(), binTable(), 8, "PDF, 6 Inferno bins");
    expectBar(page, page.rect(), depthTable(), 3, "PDF, chromadepth");
    // The view is stored losslessly (no JPEG shifting its colours).
    std::string images;
    ASSERT_EQ(test::runTool("pdfimages -list '" + (dir() / "report.pdf").string() + "'", images), 0)
        << images;
    EXPECT_NE(images.find("image"), std::string::npos) << images;
    EXPECT_EQ(images.find("jpeg"), std::string::npos) << images;
}

class ExportedLegendTest : public ::testing::Test {
  protected:
    void SetUp() override {
        test::ensureGuiApplication();
        renderer_ = test::makeRenderer();
        ASSERT_TRUE(renderer_);
    }
    std::unique_ptr<render::OffscreenRenderer> renderer_;
};

TEST_F(ExportedLegendTest, PngAndSecondaryCaptureLegendsShowTheColourMapsColours) {
    scene::Scene scene;
    scene.meshes.push_back(test::makeTube("tube"));
    ReportJobOptions o;
    o.view.width = 1600;
    o.view.height = 1200;
    o.view.display.style.array = "wss";
    o.view.display.style.colorMap = colormaps::ColorMap::Inferno;
    o.view.display.style.bins = kBins;
    o.view.display.vss.enabled = true;
    o.view.display.vss.scale = colormaps::DepthScale::Chromadepth;
    o.view.display.ao.enabled = false;
    const fs::path dir = test::testDir("legend-exports");
    o.outputs.png = dir / "view.png";
    o.outputs.dicomSc = dir / "view.dcm";
    (void)runReportJob(*renderer_, scene, o);

    const QImage png = QImage(QString::fromStdString(o.outputs.png.string()))
                           .convertToFormat(QImage::Format_RGB32);
    const QImage sc = readSecondaryCapture(o.outputs.dicomSc);
    for (const auto& [image, name] : {std::pair{png, "PNG"}, std::pair{sc, "Secondary Capture"}}) {
        ASSERT_EQ(image.size(), QSize(1600, 1200)) << name;
        // Only inside the legend boxes: the tube itself shows the bins too.
        render::Legends legends;
        legends.depth = render::DepthLegend{};
        legends.parameter = render::ParameterLegend{};
        const render::LegendLayout layout =
            render::legendLayout(QRectF(0.0, 0.0, image.width(), image.height()), legends);
        expectBar(image, layout.parameter.toAlignedRect(), binTable(), 8,
                  std::string(name) + ", 6 Inferno bins");
        expectBar(image, layout.depth.toAlignedRect(), depthTable(), 3,
                  std::string(name) + ", chromadepth");
    }
}

}  // namespace
}  // namespace vv::report
