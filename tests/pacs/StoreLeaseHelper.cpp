// SPDX-License-Identifier: GPL-3.0-or-later
// vv_store_lease_helper ROOT STUDY_UID: another process holding a study of
// the store open. Takes LocalStore::open(STUDY_UID), prints "leased" and
// holds the lease until its standard input closes (at most 60 s).
#include <poll.h>
#include <unistd.h>

#include <cstdio>
#include <exception>

#include "vv/pacs/LocalStore.h"

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: vv_store_lease_helper ROOT STUDY_UID\n");
        return 2;
    }
    try {
        const vv::pacs::LocalStore store(argv[1]);
        const vv::pacs::LocalStore::OpenLease lease = store.open(argv[2]);
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
