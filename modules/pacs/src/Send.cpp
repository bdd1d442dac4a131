// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/pacs/Send.h"

#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <dcmtk/dcmdata/dcxfer.h>

#include <map>
#include <set>

#include "Association.h"
#include "vv/core/Error.h"

namespace vv::pacs {

namespace {

/// DIMSE status "Refused: SOP Class not supported".
constexpr std::uint16_t kSopClassNotSupported = 0x0122;

/// SOP class and transfer syntax of `file`; throws FormatError.
std::pair<std::string, std::string> describeFile(const std::filesystem::path& file) {
    DcmFileFormat format;
    if (format.loadFile(file.c_str(), EXS_Unknown, EGL_noChange, 1024).bad()) {
        throw FormatError(file, "not a DICOM file");
    }
    OFString sopClass;
    if (format.getDataset()->findAndGetOFString(DCM_SOPClassUID, sopClass).bad() ||
        sopClass.empty()) {
        throw FormatError(file, "DICOM file without a SOP Class UID");
    }
    const DcmXfer xfer(format.getDataset()->getOriginalXfer());
    return {sopClass.c_str(), xfer.getXferID()};
}

}  // namespace

std::vector<SendStatus> sendFiles(const LocalAe& me, const Node& peer,
                                  const std::vector<std::filesystem::path>& files,
                                  const Progress& progress) {
    std::map<std::string, std::set<std::string>> contexts;
    std::vector<std::string> sopClasses;
    for (const auto& file : files) {
        const auto [sopClass, xfer] = describeFile(file);
        contexts[sopClass].insert(xfer);
        sopClasses.push_back(sopClass);
    }
    detail::Scu scu;
    detail::configure(scu, me, peer);
    for (const auto& [sopClass, syntaxes] : contexts) {
        for (const std::string& xfer : syntaxes) {
            OFList<OFString> list;
            list.push_back(xfer.c_str());
            if (xfer != UID_LittleEndianExplicitTransferSyntax) {
                list.push_back(UID_LittleEndianExplicitTransferSyntax);
            }
            scu.addPresentationContext(sopClass.c_str(), list);
        }
    }
    detail::open(scu, peer);
    std::vector<SendStatus> statuses;
    for (std::size_t i = 0; i < files.size(); ++i) {
        if (progress.cancelled()) {
            scu.abortAssociation();
            throw CancelledError();
        }
        if (scu.findAnyPresentationContextID(sopClasses[i].c_str(), "") == 0) {
            // The node accepts no presentation context for this SOP class.
            statuses.push_back({files[i], false, kSopClassNotSupported});
            continue;
        }
        Uint16 status = 0;
        const OFCondition cond = scu.sendSTORERequest(0, files[i].c_str(), nullptr, status);
        if (cond.bad()) {
            detail::fail(cond, peer, "C-STORE");
        }
        const bool accepted = status == STATUS_Success || (status & 0xF000) == 0xB000;
        statuses.push_back({files[i], accepted, status});
        progress.report(static_cast<double>(i + 1) / static_cast<double>(files.size()), "Sending");
    }
    detail::release(scu);
    return statuses;
}

}  // namespace vv::pacs
