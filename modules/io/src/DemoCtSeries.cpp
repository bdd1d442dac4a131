// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/io/DemoCtSeries.h"

#include <dcmtk/config/osconfig.h>  // must come first
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <dcmtk/dcmdata/dcuid.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <system_error>
#include <vector>

#include "vv/core/AtomicFile.h"
#include "vv/core/Error.h"

namespace vv::io {

namespace {

double distanceToSegment(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b) {
    const glm::dvec3 ab = b - a;
    const double len2 = glm::dot(ab, ab);
    const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    return glm::length(p - (a + t * ab));
}

std::string newUid() {
    char buffer[100];
    dcmGenerateUniqueIdentifier(buffer, SITE_INSTANCE_UID_ROOT);
    return buffer;
}

std::string ds(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%.10g", v);
    return b;
}

std::string ds3(const glm::dvec3& v) {
    return ds(v.x) + "\\" + ds(v.y) + "\\" + ds(v.z);
}

}  // namespace

bool DemoCt::inBone(const glm::dvec3& p, double margin) const {
    const glm::dvec3 q = glm::transpose(frame) * p;
    return glm::all(glm::greaterThanEqual(q, boneMin - margin)) &&
           glm::all(glm::lessThanEqual(q, boneMax + margin));
}

DemoCt generateDemoCt(const DemoCtOptions& options, const Progress& progress) {
    const glm::ivec3 dims = options.dims;
    if (glm::any(glm::lessThan(dims, glm::ivec3(8))) ||
        glm::any(glm::greaterThan(dims, glm::ivec3(2048)))) {
        throw InvalidArgumentError("demo CT: dimensions must be 8..2048 voxels");
    }
    if (!(options.noiseSigma >= 0.0) || !std::isfinite(options.noiseSigma) ||
        !std::isfinite(options.angleDegrees)) {
        throw InvalidArgumentError("demo CT: noise and angle must be finite, noise >= 0");
    }
    const char* stage = "Voxelising the demo tree";
    progress.report(0.0, stage);
    DemoCt cta;
    cta.treeOptions.generations = options.generations;
    cta.treeOptions.rootRadiusMm = 3.0;
    cta.tree = generateVesselTree(cta.treeOptions);  // validates generations

    const double a = glm::radians(options.angleDegrees);
    const glm::dvec3 row(std::cos(a), std::sin(a), 0.0);
    const glm::dvec3 column(-std::sin(a), std::cos(a), 0.0);
    const glm::dvec3 normal = glm::cross(row, column);
    cta.frame = glm::dmat3(row, column, normal);
    const glm::dmat3 toFrame = glm::transpose(cta.frame);

    // The tree's extent in frame coordinates, with a margin; the bone block
    // goes beside it on the +u side.
    glm::dvec3 lo(std::numeric_limits<double>::max());
    glm::dvec3 hi(std::numeric_limits<double>::lowest());
    for (const auto& segment : cta.tree.segments) {
        for (const glm::vec3& p : segment.centerline) {
            const glm::dvec3 q = toFrame * glm::dvec3(p);
            lo = glm::min(lo, q - segment.radiusMm);
            hi = glm::max(hi, q + segment.radiusMm);
        }
    }
    const double margin = 4.0;
    lo -= margin;
    hi += margin;
    const glm::dvec3 extent = hi - lo;
    const double block = 0.3 * std::min(extent.y, extent.z);
    cta.boneMin = glm::dvec3(hi.x + 2.0, lo.y + 0.35 * extent.y, lo.z + 0.35 * extent.z);
    cta.boneMax = cta.boneMin + block;
    hi.x = cta.boneMax.x + margin;

    const double inPlane = std::max((hi.x - lo.x) / (dims.x - 1), (hi.y - lo.y) / (dims.y - 1));
    const double step = (hi.z - lo.z) / (dims.z - 1);
    glm::dmat4 m(1.0);
    m[0] = glm::dvec4(row * inPlane, 0.0);
    m[1] = glm::dvec4(column * inPlane, 0.0);
    m[2] = glm::dvec4(normal * step, 0.0);
    m[3] = glm::dvec4(cta.frame * lo, 1.0);
    cta.volume = Volume(dims, VoxelType::Int16);
    cta.volume.setIndexToWorld(m);
    cta.volume.setModality("CT");
    cta.volume.setUnit("HU");
    const glm::dmat4 toIndex = glm::inverse(m);

    // Signed distance to the union of tubes, in each centreline piece's box.
    std::vector<float> sd(cta.volume.voxelCount(), std::numeric_limits<float>::max());
    const double h = std::cbrt(inPlane * inPlane * step);  // a voxel's size
    for (std::size_t s = 0; s < cta.tree.segments.size(); ++s) {
        const auto& segment = cta.tree.segments[s];
        progress.report(
            0.5 * static_cast<double>(s) / static_cast<double>(cta.tree.segments.size()), stage);
        const double r = segment.radiusMm;
        for (std::size_t n = 0; n + 1 < segment.centerline.size(); ++n) {
            const glm::dvec3 p0(segment.centerline[n]);
            const glm::dvec3 p1(segment.centerline[n + 1]);
            const glm::dvec3 bmin = glm::min(p0, p1) - (r + 2.0 * h);
            const glm::dvec3 bmax = glm::max(p0, p1) + (r + 2.0 * h);
            glm::dvec3 imin(std::numeric_limits<double>::max());
            glm::dvec3 imax(std::numeric_limits<double>::lowest());
            for (int c = 0; c < 8; ++c) {
                const glm::dvec3 corner((c & 1) ? bmax.x : bmin.x, (c & 2) ? bmax.y : bmin.y,
                                        (c & 4) ? bmax.z : bmin.z);
                const glm::dvec3 idx(toIndex * glm::dvec4(corner, 1.0));
                imin = glm::min(imin, idx);
                imax = glm::max(imax, idx);
            }
            const glm::ivec3 i0 = glm::max(glm::ivec3(glm::floor(imin)), glm::ivec3(0));
            const glm::ivec3 i1 = glm::min(glm::ivec3(glm::ceil(imax)), dims - 1);
            for (int k = i0.z; k <= i1.z; ++k) {
                for (int j = i0.y; j <= i1.y; ++j) {
                    for (int i = i0.x; i <= i1.x; ++i) {
                        const glm::dvec3 p = cta.volume.worldPosition(glm::dvec3(i, j, k));
                        float& d = sd[cta.volume.index(i, j, k)];
                        d = std::min(d, static_cast<float>(distanceToSegment(p, p0, p1) - r));
                    }
                }
            }
        }
    }

    std::mt19937 random(options.noiseSeed);
    std::normal_distribution<double> noise(0.0, options.noiseSigma);
    for (int k = 0; k < dims.z; ++k) {
        progress.report(0.5 + 0.5 * k / dims.z, stage);
        for (int j = 0; j < dims.y; ++j) {
            for (int i = 0; i < dims.x; ++i) {
                const std::size_t n = cta.volume.index(i, j, k);
                const double lumen = std::clamp(0.5 - static_cast<double>(sd[n]) / h, 0.0, 1.0);
                // Box signed distance (outside part) in frame coordinates.
                const glm::dvec3 q = toFrame * cta.volume.worldPosition(glm::dvec3(i, j, k));
                const glm::dvec3 outside =
                    glm::max(glm::max(cta.boneMin - q, q - cta.boneMax), glm::dvec3(0.0));
                const glm::dvec3 inside = glm::min(q - cta.boneMin, cta.boneMax - q);
                const double boxSd = glm::length(outside) > 0.0
                                         ? glm::length(outside)
                                         : -std::min({inside.x, inside.y, inside.z});
                const double bone = std::clamp(0.5 - boxSd / h, 0.0, 1.0);
                const double n0 = options.noiseSigma > 0.0 ? noise(random) : 0.0;
                cta.volume.setValueAt(n,
                                      static_cast<float>(40.0 + 360.0 * lumen + 960.0 * bone + n0));
            }
        }
    }
    progress.report(1.0, stage);
    return cta;
}

std::string writeCtSeries(const std::filesystem::path& folder, const Volume& volume,
                          const CtSeriesWriteOptions& options, const Progress& progress) {
    if (volume.empty()) {
        throw InvalidArgumentError(folder, "cannot write an empty volume as a CT series");
    }
    const glm::dmat4& m = volume.indexToWorld();
    const glm::dvec3 c0(m[0]);
    const glm::dvec3 c1(m[1]);
    const glm::dvec3 c2(m[2]);
    const glm::dvec3 origin(m[3]);
    const double spacingX = glm::length(c0);
    const double spacingY = glm::length(c1);
    if (!(spacingX > 0.0) || !(spacingY > 0.0) ||
        !(glm::length(glm::cross(c0, c1)) > 1e-9 * spacingX * spacingY)) {
        throw InvalidArgumentError(folder, "the volume's geometry is degenerate");
    }
    const glm::dvec3 row = c0 / spacingX;
    const glm::dvec3 column = c1 / spacingY;
    const glm::dvec3 normal = glm::normalize(glm::cross(row, column));
    const double thickness = std::abs(glm::dot(c2, normal));
    if (!(thickness > 0.0)) {
        throw InvalidArgumentError(folder, "the volume's slice step is degenerate");
    }
    std::error_code ec;
    std::filesystem::create_directories(folder, ec);
    if (ec || !std::filesystem::is_directory(folder)) {
        throw IoError(folder, "cannot create the folder" + (ec ? ": " + ec.message() : ""));
    }

    const std::string studyUid = newUid();
    const std::string seriesUid = newUid();
    const std::string frameUid = newUid();
    const std::string orientation = ds3(row) + "\\" + ds3(column);
    // DICOM order: row spacing (between rows = along the column direction), column spacing.
    const std::string pixelSpacing = ds(spacingY) + "\\" + ds(spacingX);
    const int columns = volume.dims().x;
    const int rows = volume.dims().y;
    const int slices = volume.dims().z;
    std::vector<Uint16> pixels(static_cast<std::size_t>(rows) * static_cast<std::size_t>(columns));
    const char* stage = "Writing the CT series";
    for (int k = 0; k < slices; ++k) {
        progress.report(static_cast<double>(k) / slices, stage);
        for (int j = 0; j < rows; ++j) {
            for (int i = 0; i < columns; ++i) {
                const double hu = std::round(static_cast<double>(volume.value(i, j, k)));
                pixels[static_cast<std::size_t>(j) * static_cast<std::size_t>(columns) +
                       static_cast<std::size_t>(i)] =
                    static_cast<Uint16>(std::clamp(hu + 1024.0, 0.0, 65535.0));
            }
        }
        DcmFileFormat ff;
        DcmDataset* d = ff.getDataset();
        const int instance = options.reverseInstanceNumbers ? slices - k : k + 1;
        const auto put = [d](const DcmTagKey& tag, const std::string& value) {
            d->putAndInsertString(tag, value.c_str());
        };
        put(DCM_SOPClassUID, UID_CTImageStorage);
        put(DCM_SOPInstanceUID, newUid());
        put(DCM_StudyInstanceUID, studyUid);
        put(DCM_SeriesInstanceUID, seriesUid);
        put(DCM_FrameOfReferenceUID, frameUid);
        put(DCM_SpecificCharacterSet, "ISO_IR 192");
        put(DCM_ImageType, "DERIVED\\SECONDARY\\AXIAL");
        put(DCM_PatientName, options.patientName);
        put(DCM_PatientID, options.patientId);
        put(DCM_PatientBirthDate, "");
        put(DCM_PatientSex, "O");
        put(DCM_StudyDate, "20250101");
        put(DCM_StudyTime, "120000");
        put(DCM_StudyID, "1");
        put(DCM_AccessionNumber, "");
        put(DCM_ReferringPhysicianName, "");
        put(DCM_StudyDescription, options.studyDescription);
        put(DCM_Modality, "CT");
        put(DCM_Manufacturer, "VesselView");
        put(DCM_SeriesDescription, options.seriesDescription);
        put(DCM_SeriesNumber, "1");
        put(DCM_InstanceNumber, std::to_string(instance));
        put(DCM_PositionReferenceIndicator, "");
        put(DCM_ImagePositionPatient, ds3(origin + static_cast<double>(k) * c2));
        put(DCM_ImageOrientationPatient, orientation);
        put(DCM_PixelSpacing, pixelSpacing);
        put(DCM_SliceThickness, ds(thickness));
        put(DCM_SpacingBetweenSlices, ds(thickness));
        put(DCM_KVP, "120");
        put(DCM_RescaleIntercept, "-1024");
        put(DCM_RescaleSlope, "1");
        put(DCM_RescaleType, "HU");
        put(DCM_WindowCenter, "200");
        put(DCM_WindowWidth, "800");
        put(DCM_PhotometricInterpretation, "MONOCHROME2");
        d->putAndInsertUint16(DCM_SamplesPerPixel, 1);
        d->putAndInsertUint16(DCM_Rows, static_cast<Uint16>(rows));
        d->putAndInsertUint16(DCM_Columns, static_cast<Uint16>(columns));
        d->putAndInsertUint16(DCM_BitsAllocated, 16);
        d->putAndInsertUint16(DCM_BitsStored, 16);
        d->putAndInsertUint16(DCM_HighBit, 15);
        d->putAndInsertUint16(DCM_PixelRepresentation, 0);
        d->putAndInsertUint16Array(DCM_PixelData, pixels.data(),
                                   static_cast<unsigned long>(pixels.size()));
        const std::filesystem::path file = folder / ("slice" + std::to_string(k) + ".dcm");
        writeAtomically(file, [&](const std::filesystem::path& temporary) {
            const OFCondition c = ff.saveFile(temporary.c_str(), EXS_LittleEndianExplicit);
            if (c.bad()) {
                throw IoError(file, std::string("cannot write the DICOM file: ") + c.text());
            }
        });
    }
    progress.report(1.0, stage);
    return seriesUid;
}

}  // namespace vv::io
