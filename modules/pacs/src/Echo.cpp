// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/pacs/Echo.h"

#include <utility>

#include "Association.h"

namespace vv::pacs {

void echo(const LocalAe& me, const Node& peer, std::stop_token stop) {
    detail::Scu scu;
    detail::configure(scu, me, peer);
    scu.abortOn(std::move(stop));
    detail::propose(scu, UID_VerificationSOPClass);
    detail::open(scu, peer);
    const OFCondition cond = scu.sendECHORequest(0);
    if (cond.bad()) {
        scu.throwIfStopped();
        detail::fail(cond, peer, "C-ECHO");
    }
    detail::release(scu);
}

}  // namespace vv::pacs
