// SPDX-License-Identifier: GPL-3.0-or-later
// vesselview-cli `info` and `demo`: through vv::cli::run and as a process.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "Unprivileged.h"
#include "cli/Cli.h"
#include "vv/meshio/MeshLoader.h"
#include "vv/meshio/MeshWriter.h"

namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::Not;

struct Result {
    int code = -1;
    std::string out;
    std::string err;
};

Result runCli(const std::vector<std::string>& args) {
    std::ostringstream out;
    std::ostringstream err;
    Result r;
    r.code = vv::cli::run(args, out, err);
    r.out = out.str();
    r.err = err.str();
    return r;
}

std::string shellQuote(const std::string& s) {
    std::string q = "'";
    for (const char c : s) {
        q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    }
    return q + "'";
}

/// Runs a shell command; returns its exit code and standard output.
Result runProcess(const std::string& command) {
    Result r;
    std::FILE* pipe = ::popen(command.c_str(), "r");
    if (pipe == nullptr) {
        return r;
    }
    char buffer[4096];
    std::size_t n = 0;
    while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) {
        r.out.append(buffer, n);
    }
    const int status = ::pclose(pipe);
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

// ---------------------------------------------------------------------------
// A minimal JSON parser: enough to check the output is valid JSON and to read
// values back.

struct Json {
    enum class Type { Null, Bool, Number, String, Array, Object } type = Type::Null;
    bool boolean = false;
    double number = 0.0;
    std::string string;
    std::vector<Json> array;
    std::vector<std::pair<std::string, Json>> object;

    [[nodiscard]] const Json& operator[](const std::string& key) const {
        for (const auto& [k, v] : object) {
            if (k == key)
                return v;
        }
        throw std::out_of_range("no key " + key);
    }
    [[nodiscard]] bool has(const std::string& key) const {
        for (const auto& kv : object) {
            if (kv.first == key)
                return true;
        }
        return false;
    }
};

class JsonParser {
  public:
    explicit JsonParser(std::string text) : s_(std::move(text)) {}

    Json parse() {
        Json v = value();
        space();
        if (i_ != s_.size())
            fail("trailing characters");
        return v;
    }

  private:
    [[noreturn]] void fail(const std::string& why) const {
        throw std::runtime_error("JSON error at " + std::to_string(i_) + ": " + why);
    }
    void space() {
        while (i_ < s_.size() &&
               (s_[i_] == ' ' || s_[i_] == '\n' || s_[i_] == '\t' || s_[i_] == '\r'))
            ++i_;
    }
    bool take(char c) {
        space();
        if (i_ < s_.size() && s_[i_] == c) {
            ++i_;
            return true;
        }
        return false;
    }
    void expect(char c) {
        if (!take(c))
            fail(std::string("expected '") + c + "'");
    }
    bool word(const char* w) {
        const std::size_t n = std::strlen(w);
        if (s_.compare(i_, n, w) == 0) {
            i_ += n;
            return true;
        }
        return false;
    }
    Json value() {
        space();
        if (i_ >= s_.size())
            fail("unexpected end");
        Json v;
        const char c = s_[i_];
        if (c == '{') {
            ++i_;
            v.type = Json::Type::Object;
            if (take('}'))
                return v;
            do {
                space();
                std::string key = stringLiteral();
                expect(':');
                v.object.emplace_back(std::move(key), value());
            } while (take(','));
            expect('}');
        } else if (c == '[') {
            ++i_;
            v.type = Json::Type::Array;
            if (take(']'))
                return v;
            do {
                v.array.push_back(value());
            } while (take(','));
            expect(']');
        } else if (c == '"') {
            v.type = Json::Type::String;
            v.string = stringLiteral();
        } else if (word("true")) {
            v.type = Json::Type::Bool;
            v.boolean = true;
        } else if (word("false")) {
            v.type = Json::Type::Bool;
        } else if (word("null")) {
            v.type = Json::Type::Null;
        } else {
            // -? (0 | [1-9][0-9]*) (. [0-9]+)? ([eE] [+-]? [0-9]+)?
            const std::size_t start = i_;
            if (s_[i_] == '-')
                ++i_;
            if (i_ >= s_.size() || std::isdigit(static_cast<unsigned char>(s_[i_])) == 0)
                fail("bad value");
            if (s_[i_] == '0') {
                ++i_;
            } else {
                while (i_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[i_])) != 0)
                    ++i_;
            }
            if (i_ < s_.size() && s_[i_] == '.') {
                ++i_;
                if (i_ >= s_.size() || std::isdigit(static_cast<unsigned char>(s_[i_])) == 0)
                    fail("bad fraction");
                while (i_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[i_])) != 0)
                    ++i_;
            }
            if (i_ < s_.size() && (s_[i_] == 'e' || s_[i_] == 'E')) {
                ++i_;
                if (i_ < s_.size() && (s_[i_] == '+' || s_[i_] == '-'))
                    ++i_;
                if (i_ >= s_.size() || std::isdigit(static_cast<unsigned char>(s_[i_])) == 0)
                    fail("bad exponent");
                while (i_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[i_])) != 0)
                    ++i_;
            }
            v.type = Json::Type::Number;
            v.number = std::strtod(s_.substr(start, i_ - start).c_str(), nullptr);
        }
        return v;
    }
    std::string stringLiteral() {
        if (i_ >= s_.size() || s_[i_] != '"')
            fail("expected a string");
        ++i_;
        std::string out;
        while (true) {
            if (i_ >= s_.size())
                fail("unterminated string");
            const auto c = static_cast<unsigned char>(s_[i_++]);
            if (c == '"')
                break;
            if (c < 0x20)
                fail("raw control character in a string");
            if (c != '\\') {
                out += static_cast<char>(c);
                continue;
            }
            if (i_ >= s_.size())
                fail("bad escape");
            const char e = s_[i_++];
            switch (e) {
                case '"':
                    out += '"';
                    break;
                case '\\':
                    out += '\\';
                    break;
                case '/':
                    out += '/';
                    break;
                case 'b':
                    out += '\b';
                    break;
                case 'f':
                    out += '\f';
                    break;
                case 'n':
                    out += '\n';
                    break;
                case 'r':
                    out += '\r';
                    break;
                case 't':
                    out += '\t';
                    break;
                case 'u': {
                    if (i_ + 4 > s_.size())
                        fail("bad \\u escape");
                    const unsigned code =
                        static_cast<unsigned>(std::stoul(s_.substr(i_, 4), nullptr, 16));
                    i_ += 4;
                    if (code >= 0xD800 && code <= 0xDFFF)
                        fail("surrogates are not expected here");
                    if (code < 0x80) {
                        out += static_cast<char>(code);
                    } else if (code < 0x800) {
                        out += static_cast<char>(0xC0 | (code >> 6));
                        out += static_cast<char>(0x80 | (code & 0x3F));
                    } else {
                        out += static_cast<char>(0xE0 | (code >> 12));
                        out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
                        out += static_cast<char>(0x80 | (code & 0x3F));
                    }
                    break;
                }
                default:
                    fail("unknown escape");
            }
        }
        return out;
    }

    std::string s_;
    std::size_t i_ = 0;
};

// ---------------------------------------------------------------------------
// Test data

class CliTest : public ::testing::Test {
  protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = fs::path(VV_TEST_TMP) / "cli" /
               (std::string(info->test_suite_name()) + "." + info->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }

    fs::path write(const std::string& name, const std::string& text) const {
        const auto file = dir_ / name;
        std::ofstream(file, std::ios::binary) << text;
        return file;
    }

    /// A tetrahedron (4 vertices, 4 triangles) as VTP: point array "wss [Pa]"
    /// with one NaN, an all-NaN point array "gap", an int cell array "label".
    fs::path tetraVtp(const std::string& name = "tetra.vtp") const {
        const float nan = std::numeric_limits<float>::quiet_NaN();
        vv::scene::Mesh m;
        m.positions = {{0, 0, 0}, {10, 0, 0}, {0, 20, 0}, {0, 0, 30}};
        m.indices = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
        vv::scene::computeNormals(m);
        vv::scene::DataArray wss;
        wss.name = "wss";
        wss.unit = "Pa";
        wss.values = {0.5F, nan, 2.5F, 1.0F};
        vv::scene::DataArray gap;
        gap.name = "gap";
        gap.values = {nan, nan, nan, nan};
        vv::scene::DataArray label;
        label.name = "label";
        label.integer = true;
        label.values = {1, 2, 3, 4};
        m.pointArrays = {wss, gap};
        m.cellArrays = {label};
        const auto file = dir_ / name;
        vv::meshio::writeVtp(m, file);
        return file;
    }

    fs::path tetraStl(const std::string& name = "tetra.stl") const {
        return write(name,
                     "solid t\n"
                     "facet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex 0 2 0\nvertex 1 0 "
                     "0\nendloop\nendfacet\n"
                     "facet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 0 "
                     "3\nendloop\nendfacet\n"
                     "facet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex 0 0 3\nvertex 0 2 "
                     "0\nendloop\nendfacet\n"
                     "facet normal 0 0 0\nouter loop\nvertex 1 0 0\nvertex 0 2 0\nvertex 0 0 "
                     "3\nendloop\nendfacet\n"
                     "endsolid t\n");
    }

    fs::path dir_;
};

// ---------------------------------------------------------------------------
// Usage errors

TEST_F(CliTest, UsageErrorsExitWithTwo) {
    for (const auto& args : std::vector<std::vector<std::string>>{
             {},
             {"frobnicate"},
             {"info"},
             {"info", "--bogus", "x.stl"},
             {"info", "x.stl", "--scale"},
             {"info", "x.stl", "--scale", "abc"},
             {"info", "x.stl", "--scale", "0"},
             {"info", "x.stl", "--scale=-2"},
             {"info", "x.stl", "--scale", "nan"},
             {"demo"},
             {"demo", "-o"},
             {"demo", "-o", "out.stl"},
             {"demo", "-o", "out.vtp", "--seed", "-1"},
             {"demo", "-o", "out.vtp", "--generations", "many"},
             {"demo", "-o", "out.vtp", "--voxel-size", "fine"},
             {"demo", "-o", "out.vtp", "--wat"},
             {"demo", "-o", "out.vtp", "stray"},
         }) {
        std::string joined;
        for (const auto& a : args)
            joined += a + " ";
        SCOPED_TRACE(joined);
        const Result r = runCli(args);
        EXPECT_EQ(r.code, vv::cli::kUsage);
        EXPECT_THAT(r.err, HasSubstr("usage"));
        EXPECT_EQ(r.out, "");
    }
}

TEST_F(CliTest, UsageErrorNamesTheBadOption) {
    const Result r = runCli({"info", "--colour", "x.stl"});
    EXPECT_EQ(r.code, vv::cli::kUsage);
    EXPECT_THAT(r.err, HasSubstr("--colour"));
}

TEST_F(CliTest, OutOfRangeDemoOptionsAreUsageErrors) {
    // Range checks live in the demo generator (InvalidArgumentError -> 2).
    const Result r = runCli({"demo", "-o", (dir_ / "d.vtp").string(), "--generations", "0"});
    EXPECT_EQ(r.code, vv::cli::kUsage);
    EXPECT_FALSE(fs::exists(dir_ / "d.vtp"));
}

TEST_F(CliTest, SubcommandHelp) {
    Result r = runCli({"info", "--help"});
    EXPECT_EQ(r.code, vv::cli::kOk);
    EXPECT_THAT(r.out, HasSubstr("--json"));
    r = runCli({"demo", "-h"});
    EXPECT_EQ(r.code, vv::cli::kOk);
    EXPECT_THAT(r.out, HasSubstr("--generations"));
}

// ---------------------------------------------------------------------------
// info

TEST_F(CliTest, InfoOnAMissingFileExitsWithThreeNamingIt) {
    const auto missing = dir_ / "missing.stl";
    const Result r = runCli({"info", missing.string()});
    EXPECT_EQ(r.code, vv::cli::kInvalidInput);
    EXPECT_THAT(r.err, HasSubstr(missing.string()));
    EXPECT_THAT(r.err, HasSubstr("not found"));
    EXPECT_EQ(r.out, "");
}

TEST_F(CliTest, InfoOnBadInputExitsWithThree) {
    const auto corrupt = write("corrupt.stl", "solid x\nfacet normal 0 0 0\nouter loop\n");
    Result r = runCli({"info", corrupt.string()});
    EXPECT_EQ(r.code, vv::cli::kInvalidInput);
    EXPECT_THAT(r.err, HasSubstr(corrupt.string()));
    const auto text = write("notes.txt", "hello");
    r = runCli({"info", text.string()});
    EXPECT_EQ(r.code, vv::cli::kInvalidInput);
    EXPECT_THAT(r.err, HasSubstr("extension"));
    r = runCli({"info", dir_.string() + "/"});
    EXPECT_EQ(r.code, vv::cli::kInvalidInput);
}

TEST_F(CliTest, InfoPrintsCountsBoundsAndArrays) {
    const auto file = tetraVtp();
    const Result r = runCli({"info", file.string()});
    ASSERT_EQ(r.code, vv::cli::kOk) << r.err;
    EXPECT_EQ(r.err, "");
    EXPECT_THAT(r.out, HasSubstr(file.string()));
    EXPECT_THAT(r.out, HasSubstr("vertices:   4\n"));
    EXPECT_THAT(r.out, HasSubstr("triangles:  4\n"));
    EXPECT_THAT(r.out, HasSubstr("x [0, 10]"));
    EXPECT_THAT(r.out, HasSubstr("z [0, 30]"));
    // wss: unit, finite range 0.5 .. 2.5, one non-finite value.
    EXPECT_THAT(r.out, ::testing::ContainsRegex("wss +1 +Pa +0\\.5 +2\\.5 +1"));
    EXPECT_THAT(r.out, ::testing::ContainsRegex("gap +1 +- +- +- +4"));
    EXPECT_THAT(r.out, ::testing::ContainsRegex("label +1 +- +1 +2 +0 +integer, from cells"));
    EXPECT_THAT(r.out, HasSubstr("cell arrays (1)"));
}

TEST_F(CliTest, InfoOnSeveralFilesAndScale) {
    const auto a = tetraStl();
    const auto b = tetraVtp();
    const Result r = runCli({"info", a.string(), b.string(), "--scale", "1000"});
    ASSERT_EQ(r.code, vv::cli::kOk) << r.err;
    const auto posA = r.out.find(a.string());
    const auto posB = r.out.find(b.string());
    ASSERT_NE(posA, std::string::npos);
    ASSERT_NE(posB, std::string::npos);
    EXPECT_LT(posA, posB);
    EXPECT_THAT(r.out, HasSubstr("z [0, 3000]"));
    EXPECT_THAT(r.out, HasSubstr("z [0, 30000]"));
    EXPECT_THAT(r.out, HasSubstr("point arrays: none"));
}

TEST_F(CliTest, InfoJsonIsValidAndComplete) {
    const auto file = tetraVtp();
    const Result r = runCli({"info", "--json", file.string()});
    ASSERT_EQ(r.code, vv::cli::kOk) << r.err;
    Json doc;
    ASSERT_NO_THROW(doc = JsonParser(r.out).parse()) << r.out;
    ASSERT_EQ(doc.type, Json::Type::Object);
    const Json& meshes = doc["meshes"];
    ASSERT_EQ(meshes.array.size(), 1U);
    const Json& m = meshes.array[0];
    EXPECT_EQ(m["file"].string, file.string());
    EXPECT_EQ(m["name"].string, "tetra");
    EXPECT_EQ(m["vertices"].number, 4.0);
    EXPECT_EQ(m["triangles"].number, 4.0);
    EXPECT_EQ(m["bounds_mm"]["max"].array[2].number, 30.0);
    EXPECT_EQ(m["bounds_mm"]["size"].array[1].number, 20.0);
    const Json& points = m["point_arrays"];
    ASSERT_EQ(points.array.size(), 3U);
    const Json& wss = points.array[0];
    EXPECT_EQ(wss["name"].string, "wss");
    EXPECT_EQ(wss["unit"].string, "Pa");
    EXPECT_EQ(wss["components"].number, 1.0);
    EXPECT_EQ(wss["min"].number, 0.5);
    EXPECT_EQ(wss["max"].number, 2.5);
    EXPECT_EQ(wss["non_finite"].number, 1.0);
    EXPECT_FALSE(wss["integer"].boolean);
    const Json& gap = points.array[1];
    EXPECT_EQ(gap["min"].type, Json::Type::Null) << "no finite value: null, not NaN";
    EXPECT_EQ(gap["non_finite"].number, 4.0);
    EXPECT_TRUE(points.array[2]["from_cells"].boolean);
    const Json& cells = m["cell_arrays"];
    ASSERT_EQ(cells.array.size(), 1U);
    EXPECT_EQ(cells.array[0]["name"].string, "label");
    EXPECT_TRUE(cells.array[0]["integer"].boolean);
    EXPECT_EQ(cells.array[0]["max"].number, 4.0);
}

TEST_F(CliTest, InfoJsonEscapesAwkwardFileNames) {
    const std::string awkward = "we\"ird\\name\ttab\x01.stl";
    const auto file = tetraStl(awkward);
    const Result r = runCli({"info", file.string(), "--json"});
    ASSERT_EQ(r.code, vv::cli::kOk) << r.err;
    Json doc;
    ASSERT_NO_THROW(doc = JsonParser(r.out).parse()) << r.out;
    EXPECT_EQ(doc["meshes"].array[0]["file"].string, file.string());
    EXPECT_THAT(r.out, HasSubstr("\\\"ird\\\\name\\ttab\\u0001"));
}

TEST_F(CliTest, InfoJsonIsAllOrNothing) {
    const Result r =
        runCli({"info", "--json", tetraVtp().string(), (dir_ / "missing.vtp").string()});
    EXPECT_EQ(r.code, vv::cli::kInvalidInput);
    EXPECT_EQ(r.out, "") << "no half-written JSON";
    EXPECT_THAT(r.err, HasSubstr("missing.vtp"));
}

TEST_F(CliTest, InfoReadsFilesNamedLikeOptionsAfterDoubleDash) {
    const auto file = tetraStl("-odd.stl");
    Result r = runCli({"info", file.filename().string()});
    EXPECT_EQ(r.code, vv::cli::kUsage);
    r = runCli({"info", "--", file.string()});
    EXPECT_EQ(r.code, vv::cli::kOk) << r.err;
}

// ---------------------------------------------------------------------------
// demo

TEST_F(CliTest, DemoWritesALoadableTree) {
    const auto file = dir_ / "demo.vtp";
    const Result r = runCli(
        {"demo", "-o", file.string(), "--generations", "2", "--voxel-size", "0.6", "--seed", "7"});
    ASSERT_EQ(r.code, vv::cli::kOk) << r.err;
    EXPECT_THAT(r.out, HasSubstr(file.string()));
    EXPECT_THAT(r.out, HasSubstr("vertices"));
    const vv::scene::Mesh mesh = vv::meshio::loadMesh(file);
    EXPECT_GT(mesh.triangleCount(), 100U);
    EXPECT_THAT(r.out, HasSubstr(std::to_string(mesh.triangleCount()) + " triangles"));
    const auto* pressure = mesh.pointArray("pressure");
    ASSERT_NE(pressure, nullptr);
    EXPECT_EQ(pressure->unit, "mmHg");
    const auto* wss = mesh.pointArray("wss");
    ASSERT_NE(wss, nullptr);
    EXPECT_EQ(wss->unit, "Pa");
    const auto* segment = mesh.pointArray("segment_id");
    ASSERT_NE(segment, nullptr);
    EXPECT_TRUE(segment->integer);
    ASSERT_NE(mesh.pointArray("generation"), nullptr);

    // Same seed, same file content.
    const auto again = dir_ / "again.vtp";
    ASSERT_EQ(runCli({"demo", "--output=" + again.string(), "--generations=2", "--voxel-size=0.6",
                      "--seed=7"})
                  .code,
              vv::cli::kOk);
    std::ifstream a(file, std::ios::binary);
    std::ifstream b(again, std::ios::binary);
    EXPECT_TRUE(
        std::equal(std::istreambuf_iterator<char>(a), {}, std::istreambuf_iterator<char>(b), {}));
}

TEST_F(CliTest, DemoToAnUnwritablePlaceExitsWithFour) {
    const auto missing = dir_ / "no" / "such" / "folder" / "demo.vtp";
    Result r = runCli({"demo", "-o", missing.string(), "--generations", "2"});
    EXPECT_EQ(r.code, vv::cli::kCannotWrite);
    EXPECT_THAT(r.err, HasSubstr(missing.string()));

    const auto plain = write("plain.txt", "x");
    r = runCli({"demo", "-o", (plain / "demo.vtp").string(), "--generations", "2"});
    EXPECT_EQ(r.code, vv::cli::kCannotWrite);

    fs::create_directories(dir_ / "taken.vtp");
    r = runCli(
        {"demo", "-o", (dir_ / "taken.vtp").string(), "--generations", "2", "--voxel-size", "0.6"});
    EXPECT_EQ(r.code, vv::cli::kCannotWrite);
    EXPECT_THAT(r.err, HasSubstr("taken.vtp"));
}

TEST_F(CliTest, DemoToAReadOnlyFolderExitsWithFour) {
    const auto folder = dir_ / "read-only";
    fs::create_directories(folder);
    Result r;
    if (vv::test::runningAsRoot()) {
        // Root writes anyway: the program runs as nobody, for whom the folder
        // (searchable by all, writable by none) is read-only.
        fs::permissions(folder, fs::perms::owner_read | fs::perms::owner_exec |
                                    fs::perms::group_read | fs::perms::group_exec |
                                    fs::perms::others_read | fs::perms::others_exec);
        r = runProcess(vv::test::asNobody(shellQuote(VV_CLI_EXE) + " demo -o " +
                                          shellQuote((folder / "demo.vtp").string()) +
                                          " --generations 2 --voxel-size 0.6 2>&1"));
    } else {
        fs::permissions(folder, fs::perms::owner_read | fs::perms::owner_exec);
        r = runCli({"demo", "-o", (folder / "demo.vtp").string(), "--generations", "2",
                    "--voxel-size", "0.6"});
    }
    fs::permissions(folder, fs::perms::owner_all);
    EXPECT_EQ(r.code, vv::cli::kCannotWrite) << r.out << r.err;
    EXPECT_FALSE(fs::exists(folder / "demo.vtp"));
}

// ---------------------------------------------------------------------------
// The real executable

TEST_F(CliTest, ExecutableExitCodes) {
    const std::string exe = shellQuote(VV_CLI_EXE);
    Result r = runProcess(exe + " --version 2>/dev/null");
    EXPECT_EQ(r.code, 0);
    EXPECT_THAT(r.out, HasSubstr("vesselview-cli"));
    r = runProcess(exe + " info 2>/dev/null");
    EXPECT_EQ(r.code, 2);
    const auto missing = dir_ / "missing.stl";
    r = runProcess(exe + " info " + shellQuote(missing.string()) + " 2>&1");
    EXPECT_EQ(r.code, 3);
    EXPECT_THAT(r.out, HasSubstr(missing.string()));
    r = runProcess(exe + " demo -o " + shellQuote((dir_ / "no" / "demo.vtp").string()) +
                   " 2>/dev/null");
    EXPECT_EQ(r.code, 4);
    r = runProcess(exe + " info " + shellQuote(tetraVtp().string()) + " 2>&1");
    EXPECT_EQ(r.code, 0);
    EXPECT_THAT(r.out, HasSubstr("triangles:  4"));
    EXPECT_THAT(r.out, Not(HasSubstr("vtk"))) << "no VTK chatter on the console";
}

TEST_F(CliTest, ExecutableJsonParsesWithPython) {
    if (runProcess("python3 -c 'import json' 2>/dev/null").code != 0) {
        GTEST_SKIP() << "python3 not available";
    }
    const std::string command =
        shellQuote(VV_CLI_EXE) + " info --json " + shellQuote(tetraVtp().string()) + " " +
        shellQuote(tetraStl("we\"ird.stl").string()) +
        " | python3 -c 'import json,sys; d=json.load(sys.stdin); "
        "assert len(d[\"meshes\"]) == 2; assert d[\"meshes\"][0][\"vertices\"] == 4; "
        "assert d[\"meshes\"][0][\"point_arrays\"][1][\"min\"] is None; print(\"ok\")'";
    const Result r = runProcess(command);
    EXPECT_EQ(r.code, 0);
    EXPECT_EQ(r.out, "ok\n");
}

// DICOM ---------------------------------------------------------------------
// `info` on DICOM files and folders. The files are written byte by byte here
// (explicit VR little endian) so that this test needs no DICOM library.

std::string dicomElement(std::uint16_t group, std::uint16_t element, const char* vr,
                         std::string value) {
    const bool pixels = std::strcmp(vr, "OW") == 0 || std::strcmp(vr, "OB") == 0;
    if (value.size() % 2 != 0) {
        value += std::strcmp(vr, "UI") == 0 || pixels ? '\0' : ' ';
    }
    std::string e;
    const auto u16 = [&](std::uint32_t v) {
        e += static_cast<char>(v & 0xFFU);
        e += static_cast<char>((v >> 8U) & 0xFFU);
    };
    u16(group);
    u16(element);
    e += vr;
    if (pixels) {
        u16(0);
        u16(static_cast<std::uint32_t>(value.size()) & 0xFFFFU);
        u16(static_cast<std::uint32_t>(value.size()) >> 16U);
    } else {
        u16(static_cast<std::uint32_t>(value.size()));
    }
    return e + value;
}

std::string u16Value(std::uint16_t v) {
    return std::string{static_cast<char>(v & 0xFFU), static_cast<char>(v >> 8U)};
}

/// A 16 x 16 CT slice at z (stored values z * 10 + i, rescale -1024).
void writeDicomSlice(const fs::path& file, const std::string& series, int z) {
    const std::string sop = series + "." + std::to_string(z + 1);
    std::string meta = dicomElement(0x0002, 0x0001, "OB", std::string("\0\1", 2)) +
                       dicomElement(0x0002, 0x0002, "UI", "1.2.840.10008.5.1.4.1.1.2") +
                       dicomElement(0x0002, 0x0003, "UI", sop) +
                       dicomElement(0x0002, 0x0010, "UI", "1.2.840.10008.1.2.1");
    std::string length(4, '\0');
    for (int b = 0; b < 4; ++b) {
        length[static_cast<std::size_t>(b)] = static_cast<char>((meta.size() >> (8U * b)) & 0xFFU);
    }
    meta = dicomElement(0x0002, 0x0000, "UL", length) + meta;
    std::string pixels;
    for (int n = 0; n < 256; ++n) {
        pixels += u16Value(static_cast<std::uint16_t>(z * 10 + n % 16));
    }
    const std::string data =
        dicomElement(0x0008, 0x0016, "UI", "1.2.840.10008.5.1.4.1.1.2") +
        dicomElement(0x0008, 0x0018, "UI", sop) + dicomElement(0x0008, 0x0060, "CS", "CT") +
        dicomElement(0x0008, 0x103E, "LO", "cli angio") +
        dicomElement(0x0010, 0x0010, "PN", "Hiddenname^Pat") +
        dicomElement(0x0010, 0x0020, "LO", "PID-HIDDEN-99") +
        dicomElement(0x0020, 0x000D, "UI", "1.2.826.0.1.3680043.99.1") +
        dicomElement(0x0020, 0x000E, "UI", series) +
        dicomElement(0x0020, 0x0032, "DS", "0\\0\\" + std::to_string(2 * z)) +
        dicomElement(0x0020, 0x0037, "DS", "1\\0\\0\\0\\1\\0") +
        dicomElement(0x0028, 0x0002, "US", u16Value(1)) +
        dicomElement(0x0028, 0x0004, "CS", "MONOCHROME2") +
        dicomElement(0x0028, 0x0010, "US", u16Value(16)) +
        dicomElement(0x0028, 0x0011, "US", u16Value(16)) +
        dicomElement(0x0028, 0x0030, "DS", "0.5\\0.5") +
        dicomElement(0x0028, 0x0100, "US", u16Value(16)) +
        dicomElement(0x0028, 0x0101, "US", u16Value(16)) +
        dicomElement(0x0028, 0x0102, "US", u16Value(15)) +
        dicomElement(0x0028, 0x0103, "US", u16Value(1)) +
        dicomElement(0x0028, 0x1052, "DS", "-1024") + dicomElement(0x0028, 0x1053, "DS", "1") +
        dicomElement(0x7FE0, 0x0010, "OW", pixels);
    std::ofstream(file, std::ios::binary) << std::string(128, '\0') << "DICM" << meta << data;
}

constexpr const char* kCliSeries = "1.2.826.0.1.3680043.99.1.7";

TEST_F(CliTest, DicomInfoListsTheSeriesOfAFolder) {
    fs::create_directories(dir_ / "dicom" / "nested");
    for (int z = 0; z < 3; ++z) {
        writeDicomSlice(dir_ / "dicom" / (z == 1 ? "nested" : "") / ("slice" + std::to_string(z)),
                        kCliSeries, z);
    }
    write("dicom/readme.txt", "not DICOM");
    const Result r = runCli({"info", (dir_ / "dicom").string()});
    ASSERT_EQ(r.code, vv::cli::kOk) << r.err;
    EXPECT_THAT(r.out, HasSubstr(kCliSeries));
    EXPECT_THAT(r.out, HasSubstr("modality:    CT"));
    EXPECT_THAT(r.out, HasSubstr("description: cli angio"));
    EXPECT_THAT(r.out, HasSubstr("images:      3 in 3 files"));
    EXPECT_THAT(r.out, HasSubstr("size:        16 x 16"));
    EXPECT_THAT(r.out, HasSubstr("spacing:     0.5 x 0.5 x 2 mm"));
    EXPECT_THAT(r.out, HasSubstr("loadable:    yes"));
    EXPECT_THAT(r.out, HasSubstr("readme.txt: not a DICOM file"));
    EXPECT_THAT(r.out, Not(HasSubstr("Hiddenname")));
    EXPECT_THAT(r.out, Not(HasSubstr("PID-HIDDEN")));
}

TEST_F(CliTest, DicomInfoOnOneFileAndAsJson) {
    writeDicomSlice(dir_ / "one.dcm", kCliSeries, 4);
    Result r = runCli({"info", (dir_ / "one.dcm").string()});
    ASSERT_EQ(r.code, vv::cli::kOk) << r.err;
    EXPECT_THAT(r.out, HasSubstr("images:      1 in 1 file"));
    r = runCli({"info", "--json", (dir_ / "one.dcm").string()});
    ASSERT_EQ(r.code, vv::cli::kOk) << r.err;
    Json doc;
    ASSERT_NO_THROW(doc = JsonParser(r.out).parse()) << r.out;
    const Json& study = doc["dicom"].array.at(0)["patients"].array.at(0)["studies"].array.at(0);
    const Json& series = study["series"].array.at(0);
    EXPECT_EQ(series["series_instance_uid"].string, kCliSeries);
    EXPECT_EQ(series["modality"].string, "CT");
    EXPECT_EQ(series["images"].number, 1.0);
    EXPECT_EQ(series["rows"].number, 16.0);
    EXPECT_EQ(series["pixel_spacing_mm"].array.size(), 2U);
    EXPECT_TRUE(series["loadable"].boolean);
    EXPECT_FALSE(doc.has("meshes"));
    EXPECT_THAT(r.out, Not(HasSubstr("Hiddenname")));
}

TEST_F(CliTest, DicomInfoWithoutImagesExitsWithThree) {
    fs::create_directories(dir_ / "empty");
    write("empty/notes.txt", "nothing here");
    Result r = runCli({"info", (dir_ / "empty").string()});
    EXPECT_EQ(r.code, vv::cli::kInvalidInput);
    EXPECT_THAT(r.err, HasSubstr("no DICOM image series"));
    EXPECT_THAT(r.err, HasSubstr("empty"));
    EXPECT_EQ(r.out, "");
    r = runCli({"info", (dir_ / "no-such-folder" / "x.dcm").string()});
    EXPECT_EQ(r.code, vv::cli::kInvalidInput);
}

}  // namespace
