// SPDX-License-Identifier: GPL-3.0-or-later
#include "CsvText.h"

#include <fstream>

#include "vv/core/AtomicFile.h"
#include "vv/core/Error.h"

namespace vv::study::detail {

std::string csvField(const std::string& text) {
    if (text.find_first_of(",\"\r\n") == std::string::npos) {
        return text;
    }
    std::string out = "\"";
    for (const char c : text) {
        out += c == '"' ? std::string("\"\"") : std::string(1, c);
    }
    return out + "\"";
}

void writeTextFile(const std::filesystem::path& file, const std::string& text) {
    writeAtomically(file, [&](const std::filesystem::path& temporary) {
        std::ofstream out(temporary, std::ios::binary);
        out << text;
        out.flush();
        if (!out) {
            throw IoError(file, "cannot be written");
        }
    });
}

}  // namespace vv::study::detail
