// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

namespace vv::cli {

/// vesselview-cli report: the PDF report of a mesh (and optionally PNG,
/// DICOM Secondary Capture, DICOM Encapsulated PDF), for one input or a batch
/// list. Throws UsageError for a bad command line and lets vv::Error pass
/// (see Cli.h) for a single input; in batch mode each input's failure is
/// reported on `err`, the others are still produced, and the exit code is
/// the first failure's (kOk when all succeeded).
int reportCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace vv::cli
