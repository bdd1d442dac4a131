// SPDX-License-Identifier: GPL-3.0-or-later
#include "LabelNames.h"

#include <vtkAbstractArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkStringArray.h>

#include <charconv>
#include <string_view>

namespace vv::meshio::detail {

namespace {

constexpr std::string_view kSuffix = "_names";

void nameArrays(scene::Mesh& mesh, const std::vector<scene::DataArray>& arrays,
                vtkFieldData& field) {
    for (const scene::DataArray& array : arrays) {
        auto* names = vtkStringArray::SafeDownCast(
            field.GetAbstractArray((array.name + std::string(kSuffix)).c_str()));
        if (names == nullptr) {
            continue;
        }
        std::vector<std::string> entries;
        for (vtkIdType i = 0; i < names->GetNumberOfValues(); ++i) {
            entries.emplace_back(names->GetValue(i));
        }
        mesh.labelNames[array.name] = parseLabelNames(entries);
    }
}

}  // namespace

std::map<std::int64_t, std::string> parseLabelNames(const std::vector<std::string>& entries) {
    std::map<std::int64_t, std::string> out;
    for (std::size_t i = 0; i < entries.size(); ++i) {
        const std::string& entry = entries[i];
        auto value = static_cast<std::int64_t>(i);
        std::string name = entry;
        if (const auto eq = entry.find('='); eq != std::string::npos) {
            std::int64_t parsed = 0;
            const char* first = entry.data();
            const char* last = entry.data() + eq;
            const auto [end, error] = std::from_chars(first, last, parsed);
            if (error == std::errc() && end == last && eq > 0) {
                value = parsed;
                name = entry.substr(eq + 1);
            }
        }
        if (!name.empty()) {
            out[value] = name;
        }
    }
    return out;
}

void readLabelNames(vtkFieldData* field, scene::Mesh& mesh) {
    if (field == nullptr) {
        return;
    }
    nameArrays(mesh, mesh.pointArrays, *field);
    nameArrays(mesh, mesh.cellArrays, *field);
}

void writeLabelNames(const scene::Mesh& mesh, vtkFieldData& field) {
    for (const auto& [array, labels] : mesh.labelNames) {
        const std::string key = array + std::string(kSuffix);
        if (labels.empty() || field.GetAbstractArray(key.c_str()) != nullptr) {
            continue;
        }
        vtkNew<vtkStringArray> names;
        names->SetName(key.c_str());
        for (const auto& [value, name] : labels) {
            names->InsertNextValue(std::to_string(value) + "=" + name);
        }
        field.AddArray(names);
    }
}

}  // namespace vv::meshio::detail
