// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/study/Manifest.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QJsonParseError>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <tuple>

namespace vv::study {
namespace {

constexpr std::uintmax_t kMaxBytes = 16ULL << 20U;

class ManifestReader {
  public:
    explicit ManifestReader(std::filesystem::path file) : file_(std::move(file)) {}

    [[noreturn]] void fail(const std::string& problem) const { throw StudyError(file_, problem); }

    [[nodiscard]] QJsonObject document() const {
        std::error_code error;
        const std::uintmax_t size = std::filesystem::file_size(file_, error);
        if (error) {
            fail("cannot read the study's manifest: " + error.message());
        }
        if (size > kMaxBytes) {
            fail("the manifest is larger than 16 MiB; it is not a study manifest");
        }
        std::ifstream in(file_, std::ios::binary);
        std::ostringstream bytes;
        bytes << in.rdbuf();
        if (!in) {
            fail("cannot read the study's manifest");
        }
        const std::string text = bytes.str();
        QJsonParseError parse{};
        const QJsonDocument json = QJsonDocument::fromJson(
            QByteArray(text.data(), static_cast<qsizetype>(text.size())), &parse);
        if (parse.error != QJsonParseError::NoError) {
            fail("not JSON (" + parse.errorString().toStdString() + " at byte " +
                 std::to_string(parse.offset) + ")");
        }
        if (!json.isObject() || json.object().value("format").toString() != "vesselview-study-1") {
            fail("not a VesselView study manifest (format \"vesselview-study-1\" expected)");
        }
        return json.object();
    }

    std::string text(const QJsonObject& o, const char* key, const std::string& where) const {
        const QJsonValue v = o.value(key);
        if (!v.isString() || v.toString().isEmpty()) {
            fail(where + ": \"" + key + "\" is missing or not a text");
        }
        return v.toString().toStdString();
    }

    int whole(const QJsonObject& o, const char* key, const std::string& where, int low,
              int high) const {
        const QJsonValue v = o.value(key);
        const double d = v.toDouble(-1.0e300);
        // The range first: a cast of a number beyond long long is undefined.
        if (!v.isDouble() || !(d >= low && d <= high) || d != std::floor(d)) {
            fail(where + ": \"" + key + "\" is missing or not a whole number from " +
                 std::to_string(low) + " to " + std::to_string(high));
        }
        return static_cast<int>(d);
    }

    MarkerPixel marker(const QJsonObject& o, const char* key, const std::string& where,
                       const StudyManifest& m) const {
        const QJsonValue v = o.value(key);
        if (!v.isObject()) {
            fail(where + ": marker \"" + key + "\" is missing");
        }
        const std::string at = where + ", marker " + key;
        return {whole(v.toObject(), "x", at, 0, m.width - 1),
                whole(v.toObject(), "y", at, 0, m.height - 1)};
    }

    /// The image's path, checked to stay inside folder/stimuli.
    [[nodiscard]] std::filesystem::path image(const std::string& relative, const std::string& where,
                                              const std::filesystem::path& folder) const {
        const std::filesystem::path path(relative);
        bool inside = path.is_relative() && !path.has_root_name() && path.begin() != path.end() &&
                      *path.begin() == "stimuli" && relative.find('\\') == std::string::npos;
        for (const auto& part : path) {
            inside = inside && part != ".." && part != ".";
        }
        if (!inside) {
            fail(where + ": image \"" + relative + "\" is not a file in the folder's stimuli/");
        }
        std::filesystem::path absolute = folder / path;
        std::error_code error;
        if (!std::filesystem::is_regular_file(absolute, error)) {
            fail(where + ": image " + absolute.string() + " is missing");
        }
        return absolute;
    }

  private:
    std::filesystem::path file_;
};

}  // namespace

std::vector<std::size_t> StudyManifest::indicesOf(Block block) const {
    std::vector<std::size_t> out;
    for (std::size_t i = 0; i < stimuli.size(); ++i) {
        if (stimuli[i].block == block) {
            out.push_back(i);
        }
    }
    return out;
}

StudyManifest readManifest(const std::filesystem::path& folder) {
    std::error_code error;
    const bool isFolder = std::filesystem::is_directory(folder, error);
    const std::filesystem::path file = isFolder ? folder / "manifest.json" : folder;
    const ManifestReader r(file);
    const QJsonObject root = r.document();

    StudyManifest m;
    m.folder = std::filesystem::absolute(file).parent_path();
    m.seed = root.value("seed").toString().toStdString();
    m.width = r.whole(root, "width", "the manifest", 64, 8192);
    m.height = r.whole(root, "height", "the manifest", 64, 8192);
    std::set<std::string> conditions;
    for (const auto& c : root.value("conditions").toArray()) {
        const std::string name = r.text(c.toObject(), "name", "a condition");
        if (!conditions.insert(name).second) {
            r.fail("condition '" + name + "' is listed twice");
        }
        m.conditions.push_back(name);
    }
    if (m.conditions.empty()) {
        r.fail("the manifest lists no condition");
    }
    std::set<std::string> ids;
    // A marker pair has one image per condition and block: a second one
    // would drop the first from every participant's order.
    std::map<std::tuple<Block, std::string, int, std::string>, std::string> taken;
    const QJsonArray stimuli = root.value("stimuli").toArray();
    for (qsizetype i = 0; i < stimuli.size(); ++i) {
        const std::string where = "stimulus " + std::to_string(i + 1);
        if (!stimuli[i].isObject()) {
            r.fail(where + " is not an object");
        }
        const QJsonObject o = stimuli[i].toObject();
        ManifestStimulus s;
        s.id = r.text(o, "id", where);
        if (!ids.insert(s.id).second) {
            r.fail(where + ": id '" + s.id + "' is used twice");
        }
        const std::string named = where + " (" + s.id + ")";
        s.image = r.image(r.text(o, "image", named), named, m.folder);
        s.scene = r.text(o, "scene", named);
        s.condition = r.text(o, "condition", named);
        if (!conditions.contains(s.condition)) {
            r.fail(named + ": condition '" + s.condition + "' is not in the manifest's list");
        }
        s.pair = r.whole(o, "pair", named, 1, 1000);
        const QString block = o.value("block").toString("main");
        if (block != "main" && block != "training") {
            r.fail(named + ": block '" + block.toStdString() + "' (main or training expected)");
        }
        s.block = block == "main" ? Block::Main : Block::Training;
        const std::string answer = r.text(o, "correct_answer", named);
        if (answer != "left" && answer != "right") {
            r.fail(std::string(named)
                       .append(": correct_answer '")
                       .append(answer)
                       .append("' (left or right expected)"));
        }
        s.correctAnswer = answer == "left" ? Side::Left : Side::Right;
        const auto [slot, fresh] = taken.try_emplace({s.block, s.scene, s.pair, s.condition}, s.id);
        if (!fresh) {
            r.fail(named + ": scene '" + s.scene + "' pair " + std::to_string(s.pair) +
                   " has a second image in condition '" + s.condition + "' (the first is '" +
                   slot->second + "')");
        }
        s.left = r.marker(o, "left", named, m);
        s.right = r.marker(o, "right", named, m);
        m.stimuli.push_back(std::move(s));
    }
    if (m.indicesOf(Block::Main).empty()) {
        r.fail("the manifest lists no image for the main block");
    }
    return m;
}

}  // namespace vv::study
