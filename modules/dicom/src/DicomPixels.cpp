// SPDX-License-Identifier: GPL-3.0-or-later
// Decoding one DICOM file's pixel data into rescaled frames (DCMTK).
#include "DicomPixels.h"

#include <dcmtk/config/osconfig.h>  // must come first
#include <dcmtk/dcmdata/dcdatset.h>
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfcache.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <dcmtk/dcmdata/dcpixel.h>
#include <dcmtk/dcmdata/dcpixseq.h>
#include <dcmtk/dcmdata/dcpxitem.h>
#include <dcmtk/dcmdata/dcxfer.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "vv/core/Error.h"

namespace vv::dicom::detail {

namespace fs = std::filesystem;

namespace {

/// RLE Lossless (PS3.5 A.4.2): one fragment per frame, each starting with a
/// 64-byte header of 1..15 segment offsets, the first 64, increasing and
/// inside the fragment. DCMTK's RLE decoder reads past its input on a
/// fragment that breaks this (found by fuzzing), so it is checked first.
void checkRleFragments(DcmPixelData& pixel, std::uint64_t frames, const fs::path& path) {
    DcmPixelSequence* sequence = nullptr;
    if (pixel.getEncapsulatedRepresentation(EXS_RLELossless, nullptr, sequence).bad() ||
        sequence == nullptr || sequence->card() < 2) {
        throw FormatError(path, "the RLE pixel data has no fragments");
    }
    const unsigned long fragments = sequence->card() - 1;  // item 0: the offset table
    if (fragments != frames) {
        throw FormatError(path, "the RLE pixel data has " + std::to_string(fragments) +
                                    " fragments for " + std::to_string(frames) +
                                    " frames (RLE needs one per frame)");
    }
    const auto le32 = [](const Uint8* p) {
        return static_cast<std::uint32_t>(p[0]) | (static_cast<std::uint32_t>(p[1]) << 8U) |
               (static_cast<std::uint32_t>(p[2]) << 16U) |
               (static_cast<std::uint32_t>(p[3]) << 24U);
    };
    for (unsigned long i = 1; i <= fragments; ++i) {
        const std::string which =
            "RLE fragment " + std::to_string(i) + " of " + std::to_string(fragments);
        DcmPixelItem* item = nullptr;
        Uint8* data = nullptr;
        if (sequence->getItem(item, i).bad() || item == nullptr ||
            item->getUint8Array(data).bad()) {
            throw FormatError(path, "cannot read " + which);
        }
        const std::uint32_t length = item->getLength();
        if (data == nullptr || length < 64) {
            throw FormatError(path, which + " is shorter than its 64-byte header");
        }
        const std::uint32_t segments = le32(data);
        if (segments < 1 || segments > 15) {
            throw FormatError(path, which + " declares " + std::to_string(segments) +
                                        " segments (1..15 allowed)");
        }
        std::uint32_t previous = 0;
        for (std::uint32_t k = 0; k < segments; ++k) {
            const std::uint32_t offset = le32(data + 4 + 4 * k);
            if ((k == 0 && offset != 64) || (k > 0 && offset <= previous) || offset >= length) {
                throw FormatError(path, which + " has a bad segment offset (" +
                                            std::to_string(offset) + "): corrupt pixel data");
            }
            previous = offset;
        }
    }
}

}  // namespace

struct FrameReader::Impl {
    fs::path file;
    std::unique_ptr<DcmFileFormat> ff;
    DcmPixelData* pixel = nullptr;
    DcmFileCache cache;
    std::uint64_t lastFrame = 0;
    Uint32 nextFragment = 0;
    std::vector<Uint8> buffer;

    void open(const fs::path& path) {
        ff.reset();
        pixel = nullptr;
        file.clear();
        cache.clear();
        lastFrame = 0;
        nextFragment = 0;
        auto f = std::make_unique<DcmFileFormat>();
        std::error_code ec;
        if (!fs::is_regular_file(path, ec)) {
            throw IoError(path, "cannot be read (missing or not a regular file)");
        }
        const OFCondition status =
            f->loadFile(OFFilename(path.c_str()), EXS_Unknown, EGL_noChange, 4096, ERM_autoDetect);
        if (status.bad()) {
            throw FormatError(path,
                              std::string("cannot be parsed as DICOM (") + status.text() + ")");
        }
        DcmElement* e = nullptr;
        if (f->getDataset()->findAndGetElement(DCM_PixelData, e).bad() || e == nullptr) {
            throw FormatError(path, "has no pixel data");
        }
        pixel = dynamic_cast<DcmPixelData*>(e);
        if (pixel == nullptr) {
            throw FormatError(path, "pixel data element of an unexpected type");
        }
        if (f->getDataset()->getOriginalXfer() == EXS_RLELossless) {
            Sint32 frames = 1;
            (void)f->getDataset()->findAndGetSint32(DCM_NumberOfFrames, frames);
            checkRleFragments(*pixel, static_cast<std::uint64_t>(std::max<Sint32>(frames, 1)),
                              path);
        }
        ff = std::move(f);
        file = path;
    }
};

FrameReader::FrameReader() : impl_(std::make_unique<Impl>()) {}
FrameReader::~FrameReader() = default;
FrameReader::FrameReader(FrameReader&& other) noexcept = default;
FrameReader& FrameReader::operator=(FrameReader&& other) noexcept = default;

void FrameReader::read(const FileHeader& h, std::uint64_t frame, double slope, double intercept,
                       std::vector<float>& out) {
    if (!impl_->ff || impl_->file != h.file) {
        impl_->open(h.file);
    }
    Impl& m = *impl_;
    DcmDataset* ds = m.ff->getDataset();
    const std::size_t count =
        static_cast<std::size_t>(h.rows) * static_cast<std::size_t>(h.columns);
    out.resize(count);
    const std::string where =
        "frame " + std::to_string(frame + 1) + " of " + std::to_string(h.frames);

    int bitsAllocated = h.bitsAllocated;
    if (h.bitsAllocated == 1) {
        const std::uint64_t bits = nativeFrameBits(h);
        const std::uint64_t firstBit = frame * bits;
        std::uint64_t begin = (firstBit / 8) & ~std::uint64_t{1};
        std::uint64_t end = (firstBit + bits + 7) / 8;
        end += end & 1U;
        const std::uint64_t total = m.pixel->getLengthField();
        end = std::min(end, total);
        if (firstBit + bits > total * 8 || end <= begin) {
            throw FormatError(h.file, "pixel data is truncated (" + where + " is missing)");
        }
        m.buffer.resize(static_cast<std::size_t>(end - begin));
        const OFCondition c =
            m.pixel->getPartialValue(m.buffer.data(), static_cast<Uint32>(begin),
                                     static_cast<Uint32>(end - begin), &m.cache, EBO_LittleEndian);
        if (c.bad()) {
            throw FormatError(h.file, "cannot read " + where + " (" + c.text() + ")");
        }
        const std::uint64_t shift = firstBit - begin * 8;
        for (std::size_t n = 0; n < count; ++n) {
            const std::uint64_t bit = shift + n;
            const int v = (m.buffer[static_cast<std::size_t>(bit / 8)] >> (bit % 8)) & 1;
            out[n] = static_cast<float>(v * slope + intercept);
        }
        return;
    }

    const std::size_t bytesPer = static_cast<std::size_t>(bitsAllocated) / 8;
    const std::size_t frameBytes = count * bytesPer;
    bool swap32 = false;
    if (!h.encapsulated) {
        const std::uint64_t total = m.pixel->getLengthField();
        if ((frame + 1) * frameBytes > total) {
            throw FormatError(h.file, "pixel data is truncated: it holds " + humanBytes(total) +
                                          ", " + where + " needs " +
                                          humanBytes((frame + 1) * frameBytes));
        }
        m.buffer.resize(frameBytes + (frameBytes & 1U));
        // 32-bit values in a big endian file: ask for the file's byte order
        // (DCMTK swaps OW data in 16-bit words) and swap whole values here.
        swap32 = bitsAllocated == 32 && h.bigEndian;
        const OFCondition c = m.pixel->getPartialValue(
            m.buffer.data(), static_cast<Uint32>(frame * frameBytes),
            static_cast<Uint32>(frameBytes), &m.cache, swap32 ? EBO_BigEndian : gLocalByteOrder);
        if (c.bad()) {
            throw FormatError(h.file, "cannot read " + where + " (" + c.text() + ")");
        }
    } else {
        Uint32 size = 0;
        if (m.pixel->getUncompressedFrameSize(ds, size).bad() || size < frameBytes) {
            throw FormatError(h.file, "cannot size the decoded " + where);
        }
        m.buffer.resize(size + (size & 1U));
        Uint32 fragment = (frame == m.lastFrame + 1 && frame > 0) ? m.nextFragment : 0;
        OFString colourModel;
        const OFCondition c = m.pixel->getUncompressedFrame(
            ds, static_cast<Uint32>(frame), fragment, m.buffer.data(),
            static_cast<Uint32>(m.buffer.size()), colourModel, &m.cache);
        if (c.bad()) {
            throw FormatError(
                h.file, "cannot decode " + where + " (" + h.transferSyntaxName + "): " + c.text());
        }
        m.lastFrame = frame;
        m.nextFragment = fragment;
    }

    const int stored = h.bitsStored;
    const int shift = std::clamp(h.highBit + 1 - stored, 0, bitsAllocated - stored);
    const std::uint32_t mask =
        stored >= 32 ? 0xFFFFFFFFU : ((std::uint32_t{1} << static_cast<unsigned>(stored)) - 1U);
    const bool isSigned = h.pixelRepresentation == 1;
    const std::uint32_t signBit = std::uint32_t{1} << static_cast<unsigned>(stored - 1);
    const Uint8* p = m.buffer.data();
    for (std::size_t n = 0; n < count; ++n) {
        std::uint32_t raw = 0;
        if (bytesPer == 1) {
            raw = p[n];
        } else if (bytesPer == 2) {
            std::uint16_t v = 0;
            std::memcpy(&v, p + 2 * n, 2);
            raw = v;
        } else {
            if (swap32) {
                const Uint8* q = p + 4 * n;
                raw = (std::uint32_t{q[0]} << 24U) | (std::uint32_t{q[1]} << 16U) |
                      (std::uint32_t{q[2]} << 8U) | std::uint32_t{q[3]};
            } else {
                std::memcpy(&raw, p + 4 * n, 4);
            }
        }
        raw = (raw >> static_cast<unsigned>(shift)) & mask;
        double v = 0;
        if (isSigned && (raw & signBit) != 0) {
            v = static_cast<double>(static_cast<std::int64_t>(raw) -
                                    (std::int64_t{1} << static_cast<unsigned>(stored)));
        } else {
            v = static_cast<double>(raw);
        }
        out[n] = static_cast<float>(v * slope + intercept);
    }
}

}  // namespace vv::dicom::detail
