// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/study/Results.h"

#include <array>
#include <charconv>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>

#include "vv/core/AtomicFile.h"
#include "vv/core/CsvField.h"

namespace vv::study {
namespace {

constexpr std::array<const char*, 10> kColumns{
    "participant", "block",  "trial",          "stimulus", "scene",
    "condition",   "answer", "correct_answer", "correct",  "response_ms"};
constexpr std::uintmax_t kMaxBytes = 64ULL << 20U;

const char* sideText(Side side) {
    return side == Side::Left ? "left" : "right";
}

/// A CSV record's fields (RFC 4180: quoted fields may hold commas, doubled
/// quotes and line breaks). `at` moves past the record and its line break;
/// `line` counts the lines it spans.
class CsvReader {
  public:
    CsvReader(std::string text, std::filesystem::path file)
        : text_(std::move(text)), file_(std::move(file)) {}

    [[nodiscard]] bool done() const noexcept { return at_ >= text_.size(); }
    [[nodiscard]] std::size_t line() const noexcept { return line_; }

    std::vector<std::string> next() {
        const std::size_t start = line_;
        std::vector<std::string> fields(1);
        bool quotedField = false;
        while (at_ < text_.size()) {
            const char c = text_[at_++];
            if (quotedField) {
                if (c == '"' && at_ < text_.size() && text_[at_] == '"') {
                    fields.back() += '"';
                    ++at_;
                } else if (c == '"') {
                    quotedField = false;
                } else {
                    line_ += c == '\n' ? 1 : 0;
                    fields.back() += c;
                }
            } else if (c == '"' && fields.back().empty()) {
                quotedField = true;
            } else if (c == ',') {
                fields.emplace_back();
            } else if (c == '\n') {
                ++line_;
                return fields;
            } else if (c != '\r') {
                fields.back() += c;
            }
        }
        if (quotedField) {
            throw StudyError(file_,
                             "line " + std::to_string(start) + ": a quoted field is not closed");
        }
        return fields;
    }

  private:
    std::string text_;
    std::filesystem::path file_;
    std::size_t at_ = 0;
    std::size_t line_ = 1;
};

std::string readAll(const std::filesystem::path& file) {
    std::error_code error;
    const std::uintmax_t size = std::filesystem::file_size(file, error);
    if (error) {
        throw StudyError(file, "cannot be read: " + error.message());
    }
    if (size > kMaxBytes) {
        throw StudyError(file, "is " + std::to_string(size >> 20U) +
                                   " MiB, more than a results file can be (64 MiB)");
    }
    std::ifstream in(file, std::ios::binary);
    if (!in) {
        throw StudyError(file, "cannot be opened");
    }
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

/// Parses one row (its fields already split) into an answer.
Answer parseRow(const std::vector<std::string>& f, const std::filesystem::path& file,
                std::size_t line) {
    const auto bad = [&](const char* column, const std::string& problem) {
        return StudyError(file,
                          "line " + std::to_string(line) + ", column " + column + ": " + problem);
    };
    const auto side = [&](std::size_t i) {
        if (f[i] == "left") {
            return Side::Left;
        }
        if (f[i] == "right") {
            return Side::Right;
        }
        throw bad(kColumns[i], "'" + f[i] + "' is neither left nor right");
    };
    Answer a;
    a.participant = f[0];
    if (f[1] == "training" || f[1] == "main") {
        a.block = f[1] == "main" ? Block::Main : Block::Training;
    } else {
        throw bad("block", "'" + f[1] + "' is neither training nor main");
    }
    const auto [end, error] = std::from_chars(f[2].data(), f[2].data() + f[2].size(), a.trial);
    if (error != std::errc() || end != f[2].data() + f[2].size() || a.trial < 1) {
        throw bad("trial", "'" + f[2] + "' is not a trial number (1, 2, ...)");
    }
    a.stimulus = f[3];
    a.scene = f[4];
    a.condition = f[5];
    a.answer = side(6);
    a.correctAnswer = side(7);
    if (f[8] != (a.correct() ? "1" : "0")) {
        throw bad("correct", "'" + f[8] + "' disagrees with the answer (" + f[6] +
                                 ") and the correct answer (" + f[7] + ")");
    }
    char* stop = nullptr;
    a.responseMs = std::strtod(f[9].c_str(), &stop);
    if (f[9].empty() || stop != f[9].c_str() + f[9].size() || !std::isfinite(a.responseMs) ||
        a.responseMs < 0.0) {
        throw bad("response_ms", "'" + f[9] + "' is not a time in ms (a number >= 0)");
    }
    for (const std::size_t i : {0U, 3U, 5U}) {
        if (f[i].empty()) {
            throw bad(kColumns[i], "is empty");
        }
    }
    return a;
}

}  // namespace

std::string resultsHeader() {
    std::string header;
    for (const char* column : kColumns) {
        header += (header.empty() ? "" : ",") + std::string(column);
    }
    return header;
}

std::string resultsRow(const Answer& a) {
    std::ostringstream row;
    row.imbue(std::locale::classic());
    row << csvField(a.participant) << ',' << (a.block == Block::Main ? "main" : "training") << ','
        << a.trial << ',' << csvField(a.stimulus) << ',' << csvField(a.scene) << ','
        << csvField(a.condition) << ',' << sideText(a.answer) << ',' << sideText(a.correctAnswer)
        << ',' << (a.correct() ? 1 : 0) << ',' << std::fixed << std::setprecision(3)
        << a.responseMs;
    return row.str();
}

std::vector<Answer> readResults(const std::filesystem::path& file) {
    CsvReader csv(readAll(file), file);
    if (csv.done()) {
        throw StudyError(file, "is empty: no header row (" + resultsHeader() + ")");
    }
    const std::vector<std::string> header = csv.next();
    if (header.size() != kColumns.size() ||
        !std::equal(header.begin(), header.end(), kColumns.begin())) {
        throw StudyError(file,
                         "line 1: the header is not a results file's (" + resultsHeader() + ")");
    }
    std::vector<Answer> answers;
    while (!csv.done()) {
        const std::size_t line = csv.line();
        const std::vector<std::string> fields = csv.next();
        if (fields.size() == 1 && fields[0].empty()) {
            continue;  // a blank line
        }
        if (fields.size() != kColumns.size()) {
            throw StudyError(file, "line " + std::to_string(line) + ": " +
                                       std::to_string(fields.size()) + " fields, not " +
                                       std::to_string(kColumns.size()));
        }
        answers.push_back(parseRow(fields, file, line));
    }
    return answers;
}

void appendAnswer(const std::filesystem::path& file, const Answer& answer) {
    std::string text;
    if (std::filesystem::exists(file)) {
        static_cast<void>(readResults(file));  // refuse to append to anything else
        text = readAll(file);
        if (!text.empty() && text.back() != '\n') {
            text += '\n';
        }
    } else {
        text = resultsHeader() + "\n";
    }
    text += resultsRow(answer) + "\n";
    writeFileAtomically(file, text);
}

}  // namespace vv::study
