// SPDX-License-Identifier: GPL-3.0-or-later
// vv::meshio's VTK extension (vtkext: for meshio, demo and segmentation only): conversion between
// vtkPolyData and vv::scene::Mesh, checks of VTK data read from untrusted files, and capture of
// VTK's diagnostic messages. Keeps VTK types out of the public headers.
#pragma once

#include <vtkObject.h>
#include <vtkSmartPointer.h>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "vv/scene/Mesh.h"

class vtkCellArray;
class vtkPolyData;
class vtkUnstructuredGrid;

namespace vv::meshio::detail {

/// Converts a polydata (any polygons; they are triangulated) into a Mesh.
/// Point and cell data arrays become DataArrays (names kept; a unit is taken
/// from a trailing " [unit]" in the name when present, see splitNameAndUnit).
/// Normals are taken from the point normals when present (or from a
/// 3-component point array called "Normals"), else computed. Non-finite array
/// values are kept as NaN.
/// Throws FormatError naming `file` for: no points, no triangles, non-finite
/// coordinates, zero total area, cells referring to points that do not exist.
/// Coordinates and connectivity are checked before any VTK filter touches them.
[[nodiscard]] scene::Mesh meshFromPolyData(vtkPolyData* polyData,
                                           const std::filesystem::path& file);

/// Converts a Mesh into a polydata with point normals, point and cell arrays.
/// Array units are kept in the array name as "name [unit]". Integer arrays
/// (DataArray::integer) with only finite values in int range become vtkIntArray,
/// all other arrays vtkFloatArray. Point arrays converted from cell arrays
/// (DataArray::fromCells) are left out when the cell array they came from is
/// in the mesh too, so that loading the polydata again recreates them.
[[nodiscard]] vtkSmartPointer<vtkPolyData> polyDataFromMesh(const scene::Mesh& mesh);

/// The bare triangle surface of `mesh`: its points (float) and triangles,
/// no normals and no arrays (a filter that weighs arrays, as the quadric
/// decimation does, must not see them). The indices must be in range.
[[nodiscard]] vtkSmartPointer<vtkPolyData> bareTriangles(const scene::Mesh& mesh);

/// Splits "wss [Pa]" into {"wss", "Pa"}; a name without brackets gives {name, ""}.
[[nodiscard]] std::pair<std::string, std::string> splitNameAndUnit(const std::string& vtkName);

/// Joins {"wss", "Pa"} into "wss [Pa]"; an empty unit gives the bare name.
[[nodiscard]] std::string joinNameAndUnit(const std::string& name, const std::string& unit);

/// The name given to a point array converted from the cell array `cellName`:
/// `cellName` itself unless `taken` (existing point array names) already holds
/// it, then "cellName (cells)", "cellName (cells 2)", ...
[[nodiscard]] std::string pointNameForCellArray(const std::string& cellName,
                                                const std::vector<std::string>& taken);

/// Checks a cell array read from a file: offsets start at 0, never decrease
/// and end at the connectivity size, and every point id is in [0, pointCount).
/// Throws FormatError naming `file`; `what` names the cells ("polygons", ...).
void checkCellArray(vtkCellArray* cells, long long pointCount, const std::filesystem::path& file,
                    const char* what);

/// The number of points a cell of VTK type `type` has when it is one the
/// loader supports: linear and the common quadratic cells; 0 for types with
/// any count >= 1 (poly-vertex, poly-line, triangle strip, polygon); -1 for
/// unsupported types (polyhedra, Lagrange, Bézier, unknown numbers).
[[nodiscard]] int supportedCellPointCount(int type) noexcept;

/// Checks an unstructured grid before filters run on it: connectivity (see
/// checkCellArray), finite coordinates, and cell types whose point count is
/// known (linear and the common quadratic cells). Polyhedra, Lagrange and
/// Bézier cells are refused. Throws FormatError naming `file`.
void checkUnstructuredGrid(vtkUnstructuredGrid* grid, const std::filesystem::path& file);

/// Collects the messages VTK reports while it is alive, on this thread.
///
/// The first instance installs, once per process, a silent vtkOutputWindow
/// and turns VTK's logger off on stderr, so nothing reaches the console. While
/// a capture lives, every VTK error / warning emitted on its thread (by any
/// object: readers, executives, arrays) is recorded here; objects passed to
/// observe() report through ErrorEvent / WarningEvent observers as well.
/// Captures nest: the innermost one on a thread receives the messages.
class VtkMessageCapture {
  public:
    VtkMessageCapture();
    ~VtkMessageCapture();
    VtkMessageCapture(const VtkMessageCapture&) = delete;
    VtkMessageCapture& operator=(const VtkMessageCapture&) = delete;

    /// Also listens to ErrorEvent and WarningEvent of `object`; keeps `object`
    /// alive until the capture ends, when the observers are removed.
    void observe(vtkObject* object);

    [[nodiscard]] bool hasErrors() const noexcept { return !errors_.empty(); }
    [[nodiscard]] bool hasMessages() const noexcept {
        return !errors_.empty() || !warnings_.empty();
    }
    /// The most telling message: the first error that is not the executive's
    /// generic "returned failure", else the first warning, else the first error;
    /// empty when nothing was reported. Cleaned of VTK's source locations and
    /// object addresses, on one line, at most ~400 characters.
    [[nodiscard]] std::string summary() const;

    /// Records a raw VTK message (used by the output window and the observers).
    void addError(const char* text);
    void addWarning(const char* text);

    /// The innermost capture of the calling thread, or nullptr.
    [[nodiscard]] static VtkMessageCapture* current() noexcept;

  private:
    std::vector<std::string> errors_;
    std::vector<std::string> warnings_;
    std::vector<std::pair<vtkSmartPointer<vtkObject>, unsigned long>> observers_;
    VtkMessageCapture* previous_ = nullptr;
};

/// Cleans a raw VTK message: drops "ERROR: In file, line n" and
/// "ClassName (0x...): " prefixes, joins lines, trims, shortens.
[[nodiscard]] std::string cleanVtkMessage(const std::string& raw);

}  // namespace vv::meshio::detail
