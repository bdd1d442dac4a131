// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// The ranges of the DICOM listener's limits (vv::pacs::ListenerLimits) one by
// one, as its validate() states them, for the front ends that offer each
// limit on its own (a spin box of DICOM > Preferences, an option of `pacs
// listen`) and name the one that is out of range. Each starts at 1 (the
// largest instance at kMinInstanceBytes). The rules between limits stay
// validate()'s: connections in all at least the simultaneous associations,
// connections per address at most the connections in all, the largest
// association at least the largest instance. PacsSettingsTest checks that
// validate() agrees.

#include <cstdint>

namespace vv::app {

inline constexpr int kMaxListenerAssociations = 256;
inline constexpr int kMaxListenerConnections = 1024;  ///< in all, and so per address
inline constexpr int kMaxListenerRequestSeconds = 120;
inline constexpr std::uint64_t kMinListenerInstanceBytes = 1000;

}  // namespace vv::app
