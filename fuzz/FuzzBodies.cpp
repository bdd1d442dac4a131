// SPDX-License-Identifier: GPL-3.0-or-later
#include "FuzzBodies.h"

#include <unistd.h>

#include <fstream>
#include <stdexcept>
#include <string>
#include <system_error>

#include "vv/core/Error.h"
#include "vv/dicom/Dicom.h"
#include "vv/meshio/MeshLoader.h"
#include "vv/vss/Pfm.h"

namespace vv::fuzz {

namespace {

/// This process's scratch folder, removed at exit (left behind on a crash).
class ScratchFolder {
  public:
    ScratchFolder() {
        std::error_code ec;
        std::filesystem::path base("/dev/shm");
        if (!std::filesystem::is_directory(base, ec)) {
            base = std::filesystem::temp_directory_path();
        }
        dir_ = base / ("vv-fuzz-" + std::to_string(::getpid()));
        std::filesystem::create_directories(dir_);
    }
    ~ScratchFolder() {
        std::error_code ec;
        std::filesystem::remove_all(dir_, ec);
    }
    ScratchFolder(const ScratchFolder&) = delete;
    ScratchFolder& operator=(const ScratchFolder&) = delete;
    [[nodiscard]] const std::filesystem::path& path() const noexcept { return dir_; }

  private:
    std::filesystem::path dir_;
};

const std::filesystem::path& scratchFolder() {
    static const ScratchFolder folder;
    return folder.path();
}

/// Runs `load`; a vv::Error becomes the outcome's error, anything else escapes.
template <class Load>
Outcome run(const std::filesystem::path& file, Load&& load) {
    Outcome outcome;
    outcome.file = file;
    try {
        load();
        outcome.loaded = true;
    } catch (const vv::Error& e) {
        outcome.error = e.what();
    }
    return outcome;
}

}  // namespace

const std::vector<std::string>& targetNames() {
    static const std::vector<std::string> names{"dicom", "stl", "obj",     "ply",      "vtp",
                                                "vtk",   "pfm", "session", "analysis", "study"};
    return names;
}

std::filesystem::path writeScratch(std::string_view name, Bytes bytes) {
    const std::filesystem::path file = scratchFolder() / std::string(name);
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(bytes.data()),
              static_cast<std::streamsize>(bytes.size()));
    out.close();
    if (!out) {
        throw std::runtime_error("fuzz: cannot write the scratch file " + file.string());
    }
    return file;
}

Outcome feedMesh(Bytes bytes, std::string_view extension) {
    const std::filesystem::path file = writeScratch("input" + std::string(extension), bytes);
    return run(file, [&] { static_cast<void>(meshio::loadMesh(file)); });
}

Outcome feedDicom(Bytes bytes) {
    const std::filesystem::path file = writeScratch("input.dcm", bytes);
    return run(file, [&] {
        dicom::DicomLoadOptions options;
        options.memoryLimitBytes = 256ULL << 20U;
        static_cast<void>(dicom::loadDicomVolume(file, {}, options));
    });
}

Outcome feedPfm(Bytes bytes) {
    const std::filesystem::path file = writeScratch("input.pfm", bytes);
    return run(file, [&] { static_cast<void>(vss::readPfm(file)); });
}

}  // namespace vv::fuzz
