// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli/Arguments.h"

#include <string>

#include "cli/Cli.h"
#include "vv/core/NumberText.h"

namespace vv::cli {

namespace {

const std::string kNone;

std::string quoted(std::string_view text) {
    return "'" + std::string(text) + "'";
}

}  // namespace

Arguments::Arguments(std::string command, const std::vector<std::string>& args, std::size_t first)
    : command_(std::move(command)), args_(args), at_(first) {}

bool Arguments::next() {
    if (started_) {
        ++at_;
    }
    started_ = true;
    inlineValue_.reset();
    if (at_ >= args_.size()) {
        name_.clear();
        return false;
    }
    name_ = args_[at_];
    if (const auto eq = name_.find('='); name_.rfind("--", 0) == 0 && eq != std::string::npos) {
        inlineValue_ = name_.substr(eq + 1);
        name_.resize(eq);
    }
    return true;
}

bool Arguments::isOption() const {
    const std::string& a = current();
    return !a.empty() && a[0] == '-' && a != "-";
}

const std::string& Arguments::value() {
    if (inlineValue_) {
        return *inlineValue_;
    }
    if (at_ + 1 >= args_.size()) {
        fail(name_ + " needs a value");
    }
    return args_[++at_];
}

std::filesystem::path Arguments::path() {
    std::filesystem::path p = value();
    if (p.empty()) {
        fail(name_ + " needs a file name");
    }
    return p;
}

const std::string& Arguments::peekValue() const {
    if (inlineValue_) {
        return *inlineValue_;
    }
    return at_ + 1 < args_.size() ? args_[at_ + 1] : kNone;
}

void Arguments::takeValue() noexcept {
    if (!inlineValue_ && at_ + 1 < args_.size()) {
        ++at_;
    }
}

void Arguments::takeOneInput(std::filesystem::path& input, bool& have) const {
    if (isOption()) {
        fail("unknown option '" + current() + "'");
    }
    if (have) {
        fail("takes one input file, got a second one '" + current() + "'");
    }
    input = current();
    have = true;
}

void Arguments::fail(const std::string& problem) const {
    throw UsageError(command_ + ": " + problem);
}

double parseNumber(std::string_view text, const std::string& what) {
    const auto value = vv::parseFiniteNumber(text);
    if (!value) {
        throw UsageError(what + " must be a number, got " + quoted(text));
    }
    return *value;
}

int parseWholeNumber(std::string_view text, const std::string& what, int lo, int hi) {
    const auto value = vv::parseWholeNumber(text);
    if (!value || *value < lo || *value > hi) {
        std::string range;
        if (lo != INT_MIN && hi != INT_MAX) {
            range = " within " + std::to_string(lo) + ".." + std::to_string(hi);
        } else if (lo != INT_MIN) {
            range = " of at least " + std::to_string(lo);
        } else if (hi != INT_MAX) {
            range = " of at most " + std::to_string(hi);
        }
        throw UsageError(what + " must be a whole number" + range + ", got " + quoted(text));
    }
    return *value;
}

std::pair<int, int> parseSize(std::string_view text, const std::string& what, int minSide,
                              int maxSide) {
    const auto x = text.find_first_of("xX");
    if (x == std::string_view::npos) {
        throw UsageError(what + " must be WIDTHxHEIGHT (e.g. 1600x1200), got " + quoted(text));
    }
    return {parseWholeNumber(text.substr(0, x), what + " width", minSide, maxSide),
            parseWholeNumber(text.substr(x + 1), what + " height", minSide, maxSide)};
}

std::vector<std::string> splitList(std::string_view text, const std::string& what) {
    std::vector<std::string> items;
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = text.find(',', start);
        const std::string_view item = text.substr(
            start, comma == std::string_view::npos ? std::string_view::npos : comma - start);
        if (item.empty()) {
            throw UsageError(what + " must be a comma-separated list, got " + quoted(text));
        }
        items.emplace_back(item);
        if (comma == std::string_view::npos) {
            return items;
        }
        start = comma + 1;
    }
}

}  // namespace vv::cli
