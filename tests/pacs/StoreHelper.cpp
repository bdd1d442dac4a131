// SPDX-License-Identifier: GPL-3.0-or-later
// vv_store_helper: another process using a study store (StoreLimitTest).
//   vv_store_helper lease ROOT STUDY_UID   takes LocalStore::open(STUDY_UID),
//       prints "leased" and holds the lease until its standard input closes
//       (at most 60 s);
//   vv_store_helper clean-up ROOT BYTES    prints "cleaning", then cleans the
//       store up to a limit of BYTES (the test kills it midway).
#include <poll.h>
#include <unistd.h>

#include <cstdio>
#include <exception>
#include <string>

#include "vv/pacs/LocalStore.h"

int main(int argc, char** argv) {
    const std::string mode = argc == 4 ? argv[1] : "";
    if (mode != "lease" && mode != "clean-up") {
        std::fprintf(stderr, "usage: vv_store_helper lease|clean-up ROOT STUDY_UID|BYTES\n");
        return 2;
    }
    try {
        vv::pacs::LocalStore store(argv[2]);
        if (mode == "clean-up") {
            store.setSizeLimit(std::stoull(argv[3]));
            std::printf("cleaning\n");
            std::fflush(stdout);
            store.cleanUp();
            return 0;
        }
        const vv::pacs::LocalStore::OpenLease lease = store.open(argv[3]);
        std::printf("leased\n");
        std::fflush(stdout);
        pollfd in{STDIN_FILENO, POLLIN, 0};
        char byte = 0;
        while (::poll(&in, 1, 60000) > 0 && ::read(STDIN_FILENO, &byte, 1) > 0) {
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 1;
    }
    return 0;
}
