// SPDX-License-Identifier: GPL-3.0-or-later
#include "ReceiveInstance.h"

#include <dcmtk/dcmdata/dcostrma.h>
#include <dcmtk/dcmdata/dcostrmf.h>

#include <memory>
#include <system_error>

namespace vv::pacs::detail {

namespace {

/// Passes at most `cap` bytes on to the file stream. Beyond the cap, or once
/// the file cannot be written, it takes the rest without writing it: DCMTK
/// then reads the dataset to its end as usual (its own way out of a failed
/// write, reading "the rest", waits for more when the failure was at the
/// last fragment), and the caller removes the file.
class CappedConsumer : public DcmConsumer {
  public:
    CappedConsumer(DcmOutputStream& file, std::uint64_t cap) : file_(file), cap_(cap) {}

    [[nodiscard]] OFBool good() const override { return OFTrue; }
    [[nodiscard]] OFCondition status() const override { return EC_Normal; }
    [[nodiscard]] OFBool isFlushed() const override { return OFTrue; }
    [[nodiscard]] offile_off_t avail() const override { return file_.avail(); }
    offile_off_t write(const void* buf, offile_off_t buflen) override {
        if (over_ || failed_ || buflen <= 0) {
            return buflen;
        }
        if (written_ + static_cast<std::uint64_t>(buflen) > cap_) {
            over_ = true;
            return buflen;
        }
        const offile_off_t n = file_.write(buf, buflen);
        if (n != buflen || !file_.good()) {
            failed_ = true;
            return buflen;
        }
        written_ += static_cast<std::uint64_t>(n);
        return n;
    }
    void flush() override {
        if (!over_ && !failed_) {
            file_.flush();
            failed_ = !file_.good();
        }
    }

    [[nodiscard]] bool over() const noexcept { return over_; }
    [[nodiscard]] bool failed() const noexcept { return failed_; }
    [[nodiscard]] std::uint64_t written() const noexcept { return written_; }

  private:
    DcmOutputStream& file_;
    std::uint64_t cap_;
    std::uint64_t written_ = 0;
    bool over_ = false;
    bool failed_ = false;
};

/// The consumer lives before the stream that points to it.
struct CappedConsumerHolder {
    CappedConsumer consumer;
};

class CappedStream : private CappedConsumerHolder, public DcmOutputStream {
  public:
    CappedStream(DcmOutputStream& file, std::uint64_t cap)
        : CappedConsumerHolder{CappedConsumer(file, cap)}, DcmOutputStream(&consumer) {}
    [[nodiscard]] const CappedConsumer& capped() const noexcept { return consumer; }
};

void removeFile(const std::filesystem::path& path) {
    std::error_code ec;
    std::filesystem::remove(path, ec);
}

}  // namespace

OFCondition receiveInstance(T_ASC_Association* association, T_DIMSE_C_StoreRQ& request,
                            T_ASC_PresentationContextID presId, const std::filesystem::path& path,
                            std::uint64_t cap, int timeoutSeconds, ReceivedInstance& result) {
    result = ReceivedInstance{};
    DcmOutputFileStream* opened = nullptr;
    OFCondition cond = DIMSE_createFilestream(path.c_str(), &request, association, presId,
                                              1 /* meta header */, &opened);
    std::unique_ptr<DcmOutputFileStream> file(opened);
    if (cond.bad()) {
        file.reset();
        removeFile(path);
        DIC_UL bytes = 0;
        DIC_UL pdvs = 0;
        cond = DIMSE_ignoreDataSet(association, DIMSE_NONBLOCKING, timeoutSeconds, &bytes, &pdvs);
        result.outcome = ReceivedInstance::Outcome::WriteFailed;
        return cond;
    }
    std::error_code ec;
    std::filesystem::permissions(
        path, std::filesystem::perms::owner_read | std::filesystem::perms::owner_write,
        std::filesystem::perm_options::replace, ec);
    T_ASC_PresentationContextID datasetPresId = presId;
    bool over = false;
    bool failed = false;
    {
        CappedStream stream(*file, cap);
        cond = DIMSE_receiveDataSetInFile(association, DIMSE_NONBLOCKING, timeoutSeconds,
                                          &datasetPresId, &stream, nullptr, nullptr);
        stream.flush();
        over = stream.capped().over();
        failed = stream.capped().failed();
        result.bytes = stream.capped().written();
    }
    file.reset();  // closes it
    if (cond.good() && datasetPresId != presId) {
        cond = makeDcmnetCondition(
            DIMSEC_INVALIDPRESENTATIONCONTEXTID, OF_error,
            "the dataset came on another presentation context than its command");
    }
    if (cond.bad() || over || failed) {
        removeFile(path);
    }
    if (cond.good() && (over || failed)) {
        result.outcome =
            over ? ReceivedInstance::Outcome::OverCap : ReceivedInstance::Outcome::WriteFailed;
    }
    return cond;
}

}  // namespace vv::pacs::detail
