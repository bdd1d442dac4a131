// SPDX-License-Identifier: GPL-3.0-or-later
// The study's results file: one CSV row per answer, as the runner appends
// them and `vesselview-cli study analyse` reads them. The columns, in this
// order, named in the header row:
//   participant    the participant's id (any text; quoted when it holds a
//                  comma, a quote or a line break)
//   block          training | main (only the main block is analysed)
//   trial          1, 2, ... within the block
//   stimulus       the stimulus' id in the study folder's manifest
//   scene          the scene it shows
//   condition      the display condition (e.g. VSS-CD)
//   answer         left | right: the marker the participant chose as closer
//   correct_answer left | right: the marker that is closer
//   correct        1 when answer is correct_answer, else 0
//   response_ms    from the stimulus on screen to the key press, ms (>= 0)
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "vv/core/Error.h"

namespace vv::study {

/// A results file or a set of answers that cannot be read or analysed:
/// what() names the file (and line) and the problem.
class StudyError : public Error {
    using Error::Error;
};

enum class Side { Left, Right };
enum class Block { Training, Main };

struct Answer {
    std::string participant;
    Block block = Block::Main;
    int trial = 0;
    std::string stimulus;
    std::string scene;
    std::string condition;
    Side answer = Side::Left;
    Side correctAnswer = Side::Left;
    double responseMs = 0.0;

    [[nodiscard]] bool correct() const noexcept { return answer == correctAnswer; }
};

/// The header row, without its line break.
[[nodiscard]] std::string resultsHeader();
/// One answer as a CSV row, without its line break.
[[nodiscard]] std::string resultsRow(const Answer& answer);

/// Reads a results file. Throws StudyError naming the file (and the line)
/// for a file that cannot be read, larger than 64 MiB, without the header
/// (columns missing, unknown or out of order), with a row of the wrong
/// number of fields, an unknown block or side, a trial that is not a
/// positive whole number, a response time that is not a finite number >= 0,
/// a `correct` that disagrees with the answer and the correct answer, an
/// empty participant, stimulus or condition, or an unterminated quote.
/// A file with the header and no rows gives no answers.
[[nodiscard]] std::vector<Answer> readResults(const std::filesystem::path& file);

/// Appends `answer` to the results file (creating it with its header):
/// the whole file written anew to a temporary file and renamed onto the old
/// one (writeAtomically), so a crash leaves the file with or without the
/// answer, never a part of it. Throws IoError when it cannot be written,
/// StudyError when the existing file is not a results file.
void appendAnswer(const std::filesystem::path& file, const Answer& answer);

}  // namespace vv::study
