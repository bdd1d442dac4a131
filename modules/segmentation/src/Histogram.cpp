// SPDX-License-Identifier: GPL-3.0-or-later
#include "Histogram.h"

namespace vv::segmentation::detail {

std::size_t otsuBin(const std::vector<std::size_t>& histogram) {
    double total = 0.0;
    double sum = 0.0;
    for (std::size_t b = 0; b < histogram.size(); ++b) {
        total += static_cast<double>(histogram[b]);
        sum += static_cast<double>(b) * static_cast<double>(histogram[b]);
    }
    double weightBelow = 0.0;
    double sumBelow = 0.0;
    double best = -1.0;
    std::size_t bestBin = 0;
    for (std::size_t b = 0; b < histogram.size(); ++b) {
        weightBelow += static_cast<double>(histogram[b]);
        sumBelow += static_cast<double>(b) * static_cast<double>(histogram[b]);
        const double weightAbove = total - weightBelow;
        if (weightBelow <= 0.0 || weightAbove <= 0.0) {
            continue;
        }
        const double meanBelow = sumBelow / weightBelow;
        const double meanAbove = (sum - sumBelow) / weightAbove;
        const double between =
            weightBelow * weightAbove * (meanBelow - meanAbove) * (meanBelow - meanAbove);
        if (between > best) {
            best = between;
            bestBin = b + 1;  // voxels in bins >= bestBin are "above"
        }
    }
    return bestBin;
}

}  // namespace vv::segmentation::detail
