// SPDX-License-Identifier: GPL-3.0-or-later
// The session target's body: separate because it needs the app's common
// library (app/common/Session.cpp); the others need only vv::meshio, vv::dicom and vv::vss.
#include <QByteArray>

#include "FuzzBodies.h"
#include "common/Session.h"
#include "vv/core/Error.h"

namespace vv::fuzz {

Outcome feedSession(Bytes bytes) {
    // sessionFromJson parses bytes; the path only resolves relative file names
    // and names the file in messages, so nothing is written.
    Outcome outcome;
    outcome.file = "/dev/shm/vv-fuzz/input.vvs";
    const QByteArray json(reinterpret_cast<const char*>(bytes.data()),
                          static_cast<qsizetype>(bytes.size()));
    try {
        static_cast<void>(app::sessionFromJson(json, outcome.file));
        outcome.loaded = true;
    } catch (const vv::Error& e) {
        outcome.error = e.what();
    }
    return outcome;
}

}  // namespace vv::fuzz
