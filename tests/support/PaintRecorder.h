// SPDX-License-Identifier: GPL-3.0-or-later
// A paint device that keeps what a QPainter draws on it instead of pixels:
// every text item (its text, where it starts, how wide it is, its font's
// pixel size) and every line, in device coordinates. Tests read from it what
// a person sees of painted text (the legends have no widget to read).
// Header only; needs a QGuiApplication (fonts).
#pragma once

#include <QFont>
#include <QLineF>
#include <QPaintDevice>
#include <QPaintEngine>
#include <QPainter>
#include <QPointF>
#include <QRectF>
#include <QString>
#include <QTextItem>
#include <QTransform>
#include <vector>

namespace vv::test {

/// One text item as drawn: `left` and `baseline` where it starts, `width` its
/// advance, all in device pixels.
struct PaintedText {
    QString text;
    double left = 0.0;
    double baseline = 0.0;
    double width = 0.0;
    double pixelSize = 0.0;
    [[nodiscard]] double right() const { return left + width; }
    [[nodiscard]] double centre() const { return left + width / 2.0; }
};

class PaintRecorder : public QPaintDevice {
  public:
    PaintRecorder(int width, int height) : width_(width), height_(height), engine_(this) {}
    PaintRecorder(const PaintRecorder&) = delete;
    PaintRecorder& operator=(const PaintRecorder&) = delete;
    PaintRecorder(PaintRecorder&&) = delete;
    PaintRecorder& operator=(PaintRecorder&&) = delete;
    ~PaintRecorder() override = default;

    [[nodiscard]] QPaintEngine* paintEngine() const override { return &engine_; }
    [[nodiscard]] const std::vector<PaintedText>& texts() const { return texts_; }
    [[nodiscard]] const std::vector<QLineF>& lines() const { return lines_; }

  protected:
    [[nodiscard]] int metric(PaintDeviceMetric m) const override {
        switch (m) {
            case PdmWidth:
                return width_;
            case PdmHeight:
                return height_;
            case PdmWidthMM:
                return width_ * 254 / 960;
            case PdmHeightMM:
                return height_ * 254 / 960;
            case PdmNumColors:
                return 1 << 24;
            case PdmDepth:
                return 32;
            case PdmDpiX:
            case PdmDpiY:
            case PdmPhysicalDpiX:
            case PdmPhysicalDpiY:
                return 96;
            case PdmDevicePixelRatio:
                return 1;
            default:
                return QPaintDevice::metric(m);
        }
    }

  private:
    class Engine : public QPaintEngine {
      public:
        explicit Engine(PaintRecorder* device) : QPaintEngine(AllFeatures), device_(device) {}
        bool begin(QPaintDevice* /*device*/) override { return true; }
        bool end() override { return true; }
        void updateState(const QPaintEngineState& changed) override {
            if ((changed.state() & DirtyTransform) != 0) {
                transform_ = changed.transform();
            }
        }
        void drawPixmap(const QRectF& /*r*/, const QPixmap& /*pm*/, const QRectF& /*sr*/) override {
        }
        void drawTextItem(const QPointF& p, const QTextItem& item) override {
            const QPointF start = transform_.map(p);
            const QPointF end = transform_.map(p + QPointF(item.width(), 0.0));
            const double size = item.font().pixelSize() > 0
                                    ? item.font().pixelSize()
                                    : item.font().pointSizeF() * 96.0 / 72.0;
            device_->texts_.push_back(
                {item.text(), start.x(), start.y(), end.x() - start.x(), size * transform_.m22()});
        }
        void drawLines(const QLineF* lines, int count) override {
            for (int i = 0; i < count; ++i) {
                device_->lines_.push_back(transform_.map(lines[i]));
            }
        }
        void drawLines(const QLine* lines, int count) override {
            for (int i = 0; i < count; ++i) {
                device_->lines_.push_back(transform_.map(QLineF(lines[i])));
            }
        }
        void drawPath(const QPainterPath& /*path*/) override {}
        void drawPolygon(const QPointF* /*points*/, int /*count*/,
                         PolygonDrawMode /*mode*/) override {}
        [[nodiscard]] Type type() const override { return User; }

      private:
        PaintRecorder* device_;
        QTransform transform_;
    };

    int width_;
    int height_;
    mutable Engine engine_;
    std::vector<PaintedText> texts_;
    std::vector<QLineF> lines_;
};

}  // namespace vv::test
