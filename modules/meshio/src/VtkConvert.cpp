// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/meshio/vtkext/VtkConvert.h"

#include <vtkCallbackCommand.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkFloatArray.h>
#include <vtkIdList.h>
#include <vtkIntArray.h>
#include <vtkLogger.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkOutputWindow.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTriangleFilter.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <mutex>
#include <string>

#include "LabelNames.h"
#include "vv/core/Error.h"

namespace vv::meshio::detail {

namespace {

// ---------------------------------------------------------------------------
// VTK message capture

thread_local VtkMessageCapture* tlsCapture = nullptr;

/// Swallows every VTK message; hands errors and warnings to the calling
/// thread's capture, if there is one.
class QuietOutputWindow : public vtkOutputWindow {
  public:
    static QuietOutputWindow* New();
    vtkTypeMacro(QuietOutputWindow, vtkOutputWindow)

        void DisplayText(const char* /*text*/) override {}
    void DisplayErrorText(const char* text) override {
        if (auto* capture = VtkMessageCapture::current()) {
            capture->addError(text);
        }
    }
    void DisplayWarningText(const char* text) override {
        if (auto* capture = VtkMessageCapture::current()) {
            capture->addWarning(text);
        }
    }
    void DisplayGenericWarningText(const char* text) override { DisplayWarningText(text); }
    void DisplayDebugText(const char* /*text*/) override {}

  protected:
    QuietOutputWindow() = default;
    ~QuietOutputWindow() override = default;
};

vtkStandardNewMacro(QuietOutputWindow);

void installQuietOutput() {
    static std::once_flag once;
    std::call_once(once, [] {
        auto window = vtkSmartPointer<QuietOutputWindow>::New();
        vtkOutputWindow::SetInstance(window);
        vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
    });
}

void onVtkEvent(vtkObject* /*caller*/, unsigned long event, void* clientData, void* callData) {
    auto* capture = static_cast<VtkMessageCapture*>(clientData);
    const char* text = static_cast<const char*>(callData);
    if (capture == nullptr) {
        return;
    }
    if (event == vtkCommand::ErrorEvent) {
        capture->addError(text);
    } else {
        capture->addWarning(text);
    }
}

bool startsWith(const std::string& s, const char* prefix) {
    return s.rfind(prefix, 0) == 0;
}

// ---------------------------------------------------------------------------
// Arrays

bool isIntegerType(int vtkType) {
    switch (vtkType) {
        case VTK_CHAR:
        case VTK_SIGNED_CHAR:
        case VTK_UNSIGNED_CHAR:
        case VTK_SHORT:
        case VTK_UNSIGNED_SHORT:
        case VTK_INT:
        case VTK_UNSIGNED_INT:
        case VTK_LONG:
        case VTK_UNSIGNED_LONG:
        case VTK_LONG_LONG:
        case VTK_UNSIGNED_LONG_LONG:
        case VTK_ID_TYPE:
            return true;
        default:
            return false;
    }
}

scene::DataArray toDataArray(vtkDataArray* array, int index) {
    scene::DataArray out;
    const char* rawName = array->GetName();
    const std::string vtkName =
        (rawName != nullptr && rawName[0] != '\0') ? rawName : "array_" + std::to_string(index);
    std::tie(out.name, out.unit) = splitNameAndUnit(vtkName);
    out.components = array->GetNumberOfComponents();
    out.integer = isIntegerType(array->GetDataType());
    const vtkIdType tuples = array->GetNumberOfTuples();
    out.values.resize(static_cast<std::size_t>(tuples) * static_cast<std::size_t>(out.components));
    for (vtkIdType t = 0; t < tuples; ++t) {
        for (int c = 0; c < out.components; ++c) {
            const double v = array->GetComponent(t, c);
            out.values[static_cast<std::size_t>(t) * static_cast<std::size_t>(out.components) +
                       static_cast<std::size_t>(c)] =
                std::isfinite(v) ? static_cast<float>(v) : std::numeric_limits<float>::quiet_NaN();
        }
    }
    return out;
}

bool fitsIntArray(const scene::DataArray& array) {
    constexpr float lo = -2147483520.0F;  // largest floats inside int range
    constexpr float hi = 2147483520.0F;
    return std::all_of(array.values.begin(), array.values.end(),
                       [=](float v) { return std::isfinite(v) && v >= lo && v <= hi; });
}

vtkSmartPointer<vtkDataArray> toVtkArray(const scene::DataArray& array) {
    const auto tuples = static_cast<vtkIdType>(array.tupleCount());
    const auto count =
        static_cast<std::size_t>(tuples) * static_cast<std::size_t>(array.components);
    if (array.integer && fitsIntArray(array)) {
        auto out = vtkSmartPointer<vtkIntArray>::New();
        out->SetName(joinNameAndUnit(array.name, array.unit).c_str());
        out->SetNumberOfComponents(array.components);
        out->SetNumberOfTuples(tuples);
        for (std::size_t i = 0; i < count; ++i) {
            out->SetValue(static_cast<vtkIdType>(i),
                          static_cast<int>(std::lround(array.values[i])));
        }
        return out;
    }
    auto out = vtkSmartPointer<vtkFloatArray>::New();
    out->SetName(joinNameAndUnit(array.name, array.unit).c_str());
    out->SetNumberOfComponents(array.components);
    out->SetNumberOfTuples(tuples);
    std::copy_n(array.values.begin(), count, out->GetPointer(0));
    return out;
}

/// True when `point` was made by converting one of `cells`.
bool derivedFromCellArray(const scene::DataArray& point,
                          const std::vector<scene::DataArray>& cells) {
    if (!point.fromCells) {
        return false;
    }
    return std::any_of(cells.begin(), cells.end(), [&](const scene::DataArray& cell) {
        return point.name == cell.name || startsWith(point.name, (cell.name + " (cells").c_str());
    });
}

// ---------------------------------------------------------------------------
// Checks

template <typename T>
void checkCellStorage(const T* offsets, vtkIdType offsetCount, const T* connectivity,
                      vtkIdType connectivityCount, long long pointCount,
                      const std::filesystem::path& file, const char* what) {
    if (offsetCount == 0) {
        return;
    }
    if (offsets[0] != 0 || static_cast<long long>(offsets[offsetCount - 1]) != connectivityCount) {
        throw FormatError(file, std::string("the ") + what + " are corrupt (bad cell offsets)");
    }
    for (vtkIdType i = 1; i < offsetCount; ++i) {
        if (offsets[i] < offsets[i - 1]) {
            throw FormatError(file, std::string("the ") + what + " are corrupt (cell " +
                                        std::to_string(i - 1) + " has a negative size)");
        }
    }
    for (vtkIdType i = 0; i < connectivityCount; ++i) {
        const auto id = static_cast<long long>(connectivity[i]);
        if (id < 0 || id >= pointCount) {
            throw FormatError(file, std::string("one of the ") + what + " refers to point " +
                                        std::to_string(id) + " but there are only " +
                                        std::to_string(pointCount) + " points");
        }
    }
}

}  // namespace

int supportedCellPointCount(int type) noexcept {
    switch (type) {
        case VTK_VERTEX:
            return 1;
        case VTK_LINE:
            return 2;
        case VTK_TRIANGLE:
            return 3;
        case VTK_PIXEL:
        case VTK_QUAD:
        case VTK_TETRA:
            return 4;
        case VTK_VOXEL:
        case VTK_HEXAHEDRON:
            return 8;
        case VTK_WEDGE:
            return 6;
        case VTK_PYRAMID:
            return 5;
        case VTK_PENTAGONAL_PRISM:
            return 10;
        case VTK_HEXAGONAL_PRISM:
            return 12;
        case VTK_QUADRATIC_EDGE:
            return 3;
        case VTK_QUADRATIC_TRIANGLE:
            return 6;
        case VTK_QUADRATIC_QUAD:
            return 8;
        case VTK_QUADRATIC_TETRA:
            return 10;
        case VTK_QUADRATIC_HEXAHEDRON:
            return 20;
        case VTK_QUADRATIC_WEDGE:
            return 15;
        case VTK_QUADRATIC_PYRAMID:
            return 13;
        case VTK_BIQUADRATIC_QUAD:
            return 9;
        case VTK_TRIQUADRATIC_HEXAHEDRON:
            return 27;
        case VTK_QUADRATIC_LINEAR_QUAD:
            return 6;
        case VTK_QUADRATIC_LINEAR_WEDGE:
            return 12;
        case VTK_BIQUADRATIC_QUADRATIC_WEDGE:
            return 18;
        case VTK_BIQUADRATIC_QUADRATIC_HEXAHEDRON:
            return 24;
        case VTK_BIQUADRATIC_TRIANGLE:
            return 7;
        case VTK_CUBIC_LINE:
            return 4;
        case VTK_POLY_VERTEX:
        case VTK_POLY_LINE:
        case VTK_TRIANGLE_STRIP:
        case VTK_POLYGON:
            return 0;
        default:
            return -1;
    }
}

vtkSmartPointer<vtkPolyData> bareTriangles(const scene::Mesh& mesh) {
    vtkNew<vtkPoints> points;
    points->SetDataTypeToFloat();
    points->SetNumberOfPoints(static_cast<vtkIdType>(mesh.vertexCount()));
    for (std::size_t i = 0; i < mesh.vertexCount(); ++i) {
        const glm::vec3& p = mesh.positions[i];
        points->SetPoint(static_cast<vtkIdType>(i), p.x, p.y, p.z);
    }
    vtkNew<vtkCellArray> triangles;
    triangles->AllocateExact(static_cast<vtkIdType>(mesh.triangleCount()),
                             static_cast<vtkIdType>(mesh.indices.size()));
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        const vtkIdType ids[3] = {static_cast<vtkIdType>(mesh.indices[3 * t]),
                                  static_cast<vtkIdType>(mesh.indices[3 * t + 1]),
                                  static_cast<vtkIdType>(mesh.indices[3 * t + 2])};
        triangles->InsertNextCell(3, ids);
    }
    auto poly = vtkSmartPointer<vtkPolyData>::New();
    poly->SetPoints(points);
    poly->SetPolys(triangles);
    return poly;
}

namespace {

void checkPointsFinite(vtkPoints* points, const std::filesystem::path& file) {
    if (points == nullptr) {
        return;
    }
    const vtkIdType count = points->GetNumberOfPoints();
    for (vtkIdType i = 0; i < count; ++i) {
        double p[3];
        points->GetPoint(i, p);
        // Finite in double but not in float (beyond ~3.4e38) is as unusable.
        const bool finite = std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]) &&
                            std::abs(p[0]) <= std::numeric_limits<float>::max() &&
                            std::abs(p[1]) <= std::numeric_limits<float>::max() &&
                            std::abs(p[2]) <= std::numeric_limits<float>::max();
        if (!finite) {
            throw FormatError(file, "point " + std::to_string(i) + " has a non-finite coordinate");
        }
    }
}

}  // namespace

// ---------------------------------------------------------------------------
// VtkMessageCapture

VtkMessageCapture::VtkMessageCapture() : previous_(tlsCapture) {
    installQuietOutput();
    tlsCapture = this;
}

VtkMessageCapture::~VtkMessageCapture() {
    for (auto& [object, tag] : observers_) {
        object->RemoveObserver(tag);
    }
    tlsCapture = previous_;
}

VtkMessageCapture* VtkMessageCapture::current() noexcept {
    return tlsCapture;
}

void VtkMessageCapture::observe(vtkObject* object) {
    if (object == nullptr) {
        return;
    }
    auto command = vtkSmartPointer<vtkCallbackCommand>::New();
    command->SetCallback(&onVtkEvent);
    command->SetClientData(this);
    observers_.emplace_back(object, object->AddObserver(vtkCommand::ErrorEvent, command));
    observers_.emplace_back(object, object->AddObserver(vtkCommand::WarningEvent, command));
}

void VtkMessageCapture::addError(const char* text) {
    errors_.emplace_back(text != nullptr ? text : "");
}

void VtkMessageCapture::addWarning(const char* text) {
    warnings_.emplace_back(text != nullptr ? text : "");
}

std::string VtkMessageCapture::summary() const {
    const auto generic = [](const std::string& m) {
        return m.find("returned failure for request") != std::string::npos;
    };
    for (const auto& e : errors_) {
        if (!generic(e)) {
            return cleanVtkMessage(e);
        }
    }
    if (!warnings_.empty()) {
        return cleanVtkMessage(warnings_.front());
    }
    if (!errors_.empty()) {
        return cleanVtkMessage(errors_.front());
    }
    return {};
}

std::string cleanVtkMessage(const std::string& raw) {
    std::string text;
    std::size_t begin = 0;
    while (begin <= raw.size()) {
        auto end = raw.find('\n', begin);
        if (end == std::string::npos) {
            end = raw.size();
        }
        std::string line = raw.substr(begin, end - begin);
        begin = end + 1;
        if (startsWith(line, "ERROR: In ") || startsWith(line, "Warning: In ") ||
            startsWith(line, "Generic Warning: In ") || startsWith(line, "Debug: In ")) {
            continue;
        }
        // "vtkSTLReader (0x55c1ab0985e0): message" -> "message"
        const auto paren = line.find(" (0x");
        if (paren != std::string::npos && line.find("): ", paren) != std::string::npos &&
            line.find(' ') == paren) {
            line = line.substr(line.find("): ", paren) + 3);
        }
        if (!text.empty() && !line.empty()) {
            text += ' ';
        }
        text += line;
        if (end == raw.size()) {
            break;
        }
    }
    // The executive appends a dump of its request; it says nothing useful.
    const auto request = text.find(" for request:");
    if (request != std::string::npos) {
        text.erase(request);
    }
    std::string collapsed;
    for (const char c : text) {
        const bool space = c == ' ' || c == '\t' || c == '\r';
        if (space && (collapsed.empty() || collapsed.back() == ' ')) {
            continue;
        }
        collapsed += space ? ' ' : c;
    }
    while (!collapsed.empty() && collapsed.back() == ' ') {
        collapsed.pop_back();
    }
    constexpr std::size_t kMax = 400;
    if (collapsed.size() > kMax) {
        collapsed.resize(kMax);
        collapsed += "...";
    }
    return collapsed;
}

// ---------------------------------------------------------------------------
// Names

std::pair<std::string, std::string> splitNameAndUnit(const std::string& vtkName) {
    const auto open = vtkName.rfind(" [");
    if (open != std::string::npos && vtkName.size() > open + 3 && vtkName.back() == ']') {
        return {vtkName.substr(0, open), vtkName.substr(open + 2, vtkName.size() - open - 3)};
    }
    return {vtkName, ""};
}

std::string joinNameAndUnit(const std::string& name, const std::string& unit) {
    return unit.empty() ? name : name + " [" + unit + "]";
}

std::string pointNameForCellArray(const std::string& cellName,
                                  const std::vector<std::string>& taken) {
    const auto free = [&](const std::string& n) {
        return std::find(taken.begin(), taken.end(), n) == taken.end();
    };
    if (free(cellName)) {
        return cellName;
    }
    std::string candidate = cellName + " (cells)";
    for (int k = 2; !free(candidate); ++k) {
        candidate = cellName + " (cells " + std::to_string(k) + ")";
    }
    return candidate;
}

// ---------------------------------------------------------------------------
// Checks

void checkCellArray(vtkCellArray* cells, long long pointCount, const std::filesystem::path& file,
                    const char* what) {
    if (cells == nullptr) {
        return;
    }
    if (cells->IsStorage64Bit()) {
        auto* offsets = cells->GetOffsetsArray64();
        auto* connectivity = cells->GetConnectivityArray64();
        checkCellStorage(offsets->GetPointer(0), offsets->GetNumberOfValues(),
                         connectivity->GetPointer(0), connectivity->GetNumberOfValues(), pointCount,
                         file, what);
    } else {
        auto* offsets = cells->GetOffsetsArray32();
        auto* connectivity = cells->GetConnectivityArray32();
        checkCellStorage(offsets->GetPointer(0), offsets->GetNumberOfValues(),
                         connectivity->GetPointer(0), connectivity->GetNumberOfValues(), pointCount,
                         file, what);
    }
}

void checkUnstructuredGrid(vtkUnstructuredGrid* grid, const std::filesystem::path& file) {
    if (grid == nullptr || grid->GetNumberOfPoints() == 0) {
        throw FormatError(file, "the file holds no points (empty mesh)");
    }
    checkPointsFinite(grid->GetPoints(), file);
    vtkCellArray* cells = grid->GetCells();
    const vtkIdType cellCount = cells != nullptr ? cells->GetNumberOfCells() : 0;
    if (cellCount == 0) {
        throw FormatError(file, "the file holds no cells (empty mesh)");
    }
    checkCellArray(cells, grid->GetNumberOfPoints(), file, "cells");
    vtkUnsignedCharArray* types = grid->GetCellTypesArray();
    if (types == nullptr || types->GetNumberOfValues() != cellCount) {
        throw FormatError(file, "the cell types do not match the cells (corrupt file)");
    }
    for (vtkIdType c = 0; c < cellCount; ++c) {
        const int type = types->GetValue(c);
        const int expected = supportedCellPointCount(type);
        if (expected < 0) {
            throw FormatError(file, "cell " + std::to_string(c) + " has type " +
                                        std::to_string(type) +
                                        ", which is not supported (only linear and common "
                                        "quadratic cells are)");
        }
        const vtkIdType size = cells->GetCellSize(c);
        if ((expected > 0 && size != expected) || (expected == 0 && size < 1)) {
            throw FormatError(file, "cell " + std::to_string(c) + " of type " +
                                        std::to_string(type) + " has " + std::to_string(size) +
                                        " points (corrupt file)");
        }
    }
}

// ---------------------------------------------------------------------------
// Conversion

scene::Mesh meshFromPolyData(vtkPolyData* input, const std::filesystem::path& file) {
    if (input == nullptr || input->GetNumberOfPoints() == 0) {
        throw FormatError(file, "the file holds no points (empty mesh)");
    }
    const vtkIdType pointCount = input->GetNumberOfPoints();
    // Untrusted data: check coordinates and connectivity before any filter
    // dereferences them.
    checkPointsFinite(input->GetPoints(), file);
    checkCellArray(input->GetVerts(), pointCount, file, "vertex cells");
    checkCellArray(input->GetLines(), pointCount, file, "lines");
    checkCellArray(input->GetPolys(), pointCount, file, "polygons");
    checkCellArray(input->GetStrips(), pointCount, file, "triangle strips");

    // Triangulate polygons and strips; lines and vertices are dropped.
    auto triangulate = vtkSmartPointer<vtkTriangleFilter>::New();
    triangulate->SetInputData(input);
    triangulate->PassVertsOff();
    triangulate->PassLinesOff();
    triangulate->Update();
    vtkPolyData* poly = triangulate->GetOutput();

    scene::Mesh mesh;
    mesh.source = file;
    mesh.name = file.stem().string();

    mesh.positions.resize(static_cast<std::size_t>(pointCount));
    for (vtkIdType i = 0; i < pointCount; ++i) {
        double p[3];
        input->GetPoint(i, p);
        mesh.positions[static_cast<std::size_t>(i)] =
            glm::vec3(static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2]));
    }

    // The triangle filter keeps point ids, so triangles index the input points.
    vtkCellArray* polys = poly->GetPolys();
    mesh.indices.reserve(static_cast<std::size_t>(polys->GetNumberOfCells()) * 3);
    std::vector<vtkIdType> sourceCell;  // output cell id of each triangle, for cell arrays
    sourceCell.reserve(static_cast<std::size_t>(polys->GetNumberOfCells()));
    auto ids = vtkSmartPointer<vtkIdList>::New();
    polys->InitTraversal();
    vtkIdType cellIndex = 0;
    const vtkIdType nonPolyCells = poly->GetNumberOfVerts() + poly->GetNumberOfLines();
    while (polys->GetNextCell(ids) != 0) {
        if (ids->GetNumberOfIds() == 3) {
            for (int k = 0; k < 3; ++k) {
                const vtkIdType id = ids->GetId(k);
                if (id < 0 || id >= pointCount) {
                    throw FormatError(file, "a triangle refers to point " + std::to_string(id) +
                                                " but there are only " +
                                                std::to_string(pointCount));
                }
                mesh.indices.push_back(static_cast<std::uint32_t>(id));
            }
            sourceCell.push_back(nonPolyCells + cellIndex);
        }
        ++cellIndex;
    }
    if (mesh.indices.empty()) {
        throw FormatError(file, "the file holds no surface triangles (empty mesh)");
    }
    double area2 = 0.0;
    for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
        area2 +=
            doubleTriangleArea(mesh.positions[mesh.indices[t]], mesh.positions[mesh.indices[t + 1]],
                               mesh.positions[mesh.indices[t + 2]]);
    }
    if (!(area2 > 0.0)) {
        throw FormatError(file, "the surface has zero area (all triangles degenerate)");
    }

    vtkPointData* pointData = input->GetPointData();
    vtkDataArray* normals = pointData->GetNormals();
    if (normals == nullptr) {
        // OBJ and PLY readers may name the array without marking it as normals.
        vtkDataArray* named = pointData->GetArray("Normals");
        if (named != nullptr && named->GetNumberOfComponents() == 3) {
            normals = named;
        }
    }
    for (int a = 0; a < pointData->GetNumberOfArrays(); ++a) {
        vtkDataArray* array = pointData->GetArray(a);
        if (array == nullptr || array == normals || array->GetNumberOfTuples() != pointCount) {
            continue;
        }
        mesh.pointArrays.push_back(toDataArray(array, a));
    }
    // Cell arrays follow the triangle filter, which copies cell data per output cell.
    vtkCellData* cellData = poly->GetCellData();
    for (int a = 0; a < cellData->GetNumberOfArrays(); ++a) {
        vtkDataArray* array = cellData->GetArray(a);
        if (array == nullptr || array->GetNumberOfTuples() != poly->GetNumberOfCells()) {
            continue;
        }
        scene::DataArray full = toDataArray(array, a);
        scene::DataArray perTriangle = full;
        perTriangle.values.clear();
        perTriangle.values.reserve(sourceCell.size() * static_cast<std::size_t>(full.components));
        const auto comps = static_cast<std::size_t>(full.components);
        for (const vtkIdType c : sourceCell) {
            const auto begin = full.values.begin() +
                               static_cast<std::ptrdiff_t>(static_cast<std::size_t>(c) * comps);
            perTriangle.values.insert(perTriangle.values.end(), begin,
                                      begin + static_cast<std::ptrdiff_t>(comps));
        }
        mesh.cellArrays.push_back(std::move(perTriangle));
    }

    bool normalsOk = normals != nullptr && normals->GetNumberOfComponents() == 3 &&
                     normals->GetNumberOfTuples() == pointCount;
    if (normalsOk) {
        mesh.normals.resize(mesh.positions.size());
        for (vtkIdType i = 0; i < pointCount && normalsOk; ++i) {
            double n[3];
            normals->GetTuple(i, n);
            glm::vec3 v(static_cast<float>(n[0]), static_cast<float>(n[1]),
                        static_cast<float>(n[2]));
            const float len = glm::length(v);
            if (!(len > 0.0F) || !std::isfinite(len)) {
                normalsOk = false;
                break;
            }
            mesh.normals[static_cast<std::size_t>(i)] = v / len;
        }
    }
    if (!normalsOk) {
        scene::computeNormals(mesh);
    }
    readLabelNames(input->GetFieldData(), mesh);
    return mesh;
}

vtkSmartPointer<vtkPolyData> polyDataFromMesh(const scene::Mesh& mesh) {
    auto points = vtkSmartPointer<vtkPoints>::New();
    points->SetDataTypeToFloat();
    points->SetNumberOfPoints(static_cast<vtkIdType>(mesh.positions.size()));
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        const auto& p = mesh.positions[i];
        points->SetPoint(static_cast<vtkIdType>(i), p.x, p.y, p.z);
    }
    auto polys = vtkSmartPointer<vtkCellArray>::New();
    polys->AllocateExact(static_cast<vtkIdType>(mesh.triangleCount()),
                         static_cast<vtkIdType>(mesh.triangleCount() * 3));
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const vtkIdType tri[3] = {mesh.indices[t], mesh.indices[t + 1], mesh.indices[t + 2]};
        polys->InsertNextCell(3, tri);
    }
    auto poly = vtkSmartPointer<vtkPolyData>::New();
    poly->SetPoints(points);
    poly->SetPolys(polys);
    if (mesh.normals.size() == mesh.positions.size()) {
        auto normals = vtkSmartPointer<vtkFloatArray>::New();
        normals->SetName("Normals");
        normals->SetNumberOfComponents(3);
        normals->SetNumberOfTuples(static_cast<vtkIdType>(mesh.normals.size()));
        for (std::size_t i = 0; i < mesh.normals.size(); ++i) {
            const auto& n = mesh.normals[i];
            normals->SetTuple3(static_cast<vtkIdType>(i), n.x, n.y, n.z);
        }
        poly->GetPointData()->SetNormals(normals);
    }
    for (const auto& array : mesh.pointArrays) {
        if (derivedFromCellArray(array, mesh.cellArrays)) {
            continue;
        }
        poly->GetPointData()->AddArray(toVtkArray(array));
    }
    for (const auto& array : mesh.cellArrays) {
        poly->GetCellData()->AddArray(toVtkArray(array));
    }
    writeLabelNames(mesh, *poly->GetFieldData());
    return poly;
}

}  // namespace vv::meshio::detail
