// SPDX-License-Identifier: MIT
// CFD flow-field import (cfddem spec 5.5) with VTK's own readers: file -> vtkDataSet -> FlowField.
//
// Why the message capture. VTK's readers do not throw: on a bad file they print "ERROR: In ..." (or
// only a warning) to the global output window and to vtkLogger's stderr, and hand back whatever they
// managed to read, often an empty or half-filled dataset (a short legacy ASCII array only gets a
// warning and keeps its declared size, the missing values uninitialised). So any error or warning
// fails the read. The reader's own messages go to observers on the reader; those of the objects it
// creates (vtkDataSetReader's concrete legacy reader, the XML parser, the pipeline executive) go to
// the output window. While a file is read we observe the reader, its executive and the output
// window, silence the window and the logger's stderr, and turn any message into a FieldFileError.
// That state is global, so reads are serialised by a mutex. The checks after reading (points > 0,
// tuple counts, finite values) catch what the readers let through without a word.
//
// Why a grid hash for the node merge: fields have up to 1e6 nodes, so the merge of equal (x, y)
// points must be O(n); a cell of the hash is one tolerance wide, so two points within the
// tolerance lie in the same or in neighbouring cells, and one cell never holds two nodes.
#include "io/flow_field_reader.hpp"

#include <vtkCellData.h>
#include <vtkCellDataToPointData.h>
#include <vtkCommand.h>
#include <vtkCompositeDataSet.h>
#include <vtkDataArray.h>
#include <vtkDataSet.h>
#include <vtkDataSetReader.h>
#include <vtkExecutive.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkInformation.h>
#include <vtkLogger.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkMultiPieceDataSet.h>
#include <vtkNew.h>
#include <vtkOutputWindow.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLImageDataReader.h>
#include <vtkXMLMultiBlockDataReader.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLRectilinearGridReader.h>
#include <vtkXMLStructuredGridReader.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <vtkXMLUtilities.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <new>
#include <nlohmann/json.hpp>
#include <sstream>
#include <unordered_map>
#include <utility>

#include "core/suggest.hpp"

namespace granulab::io {
namespace {

namespace fs = std::filesystem;

constexpr std::uint32_t kDropped = std::numeric_limits<std::uint32_t>::max();
const std::vector<std::string> kDataExtensions = {".vtk", ".vtu", ".vtr", ".vts", ".vti", ".vtm"};

std::string lowerExtension(const fs::path& p) {
    std::string ext = p.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

bool isDataFile(const fs::path& p) {
    const std::string ext = lowerExtension(p);
    return std::find(kDataExtensions.begin(), kDataExtensions.end(), ext) != kDataExtensions.end();
}

// ---------------------------------------------------------------------------------------------
// VTK message capture

/// One VTK message without its "ERROR: In <source file>, line N" header, object address and dump of
/// the pipeline request, printable and at most 200 characters: "vtkUnstructuredGridReader: Error
/// reading ascii data ...".
std::string condensed(const char* text) {
    std::istringstream in(text ? text : "");
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) {
        if (line.empty() || line.rfind("ERROR: In ", 0) == 0 || line.rfind("Warning: In ", 0) == 0 ||
            line.rfind("Generic Warning: In ", 0) == 0)
            continue;
        const std::size_t open = line.find(" (0x");
        const std::size_t close = line.find("): ", open == std::string::npos ? 0 : open);
        if (open != std::string::npos && close != std::string::npos)
            line = line.substr(0, open) + ": " + line.substr(close + 3);
        lines.push_back(line);
    }
    std::string out = joinList(lines, " ");
    for (const char* tail : {" for request:", " when asked by "})
        if (const std::size_t at = out.find(tail); at != std::string::npos) out.resize(at);
    for (char& c : out)
        if (!std::isprint(static_cast<unsigned char>(c))) c = '?';  // garbage files echo their bytes
    if (out.size() > 200) out = out.substr(0, 197) + "...";
    return out;
}

/// A message of the pipeline machinery ("Algorithm X returned failure"), not about the file.
bool isPipelineMessage(const std::string& m) {
    return m.find("Pipeline: Algorithm ") != std::string::npos || m.rfind("vtkExecutive", 0) == 0;
}

/// Collects the ErrorEvent and WarningEvent messages of the objects it observes.
class MessageSink : public vtkCommand {
public:
    static MessageSink* New() { return new MessageSink; }
    void Execute(vtkObject*, unsigned long event, void* callData) override {
        const std::string text = condensed(static_cast<const char*>(callData));
        (event == vtkCommand::ErrorEvent ? errors : warnings).push_back(text);
    }
    void observe(vtkObject* object) {
        if (!object) return;
        object->AddObserver(vtkCommand::ErrorEvent, this);
        object->AddObserver(vtkCommand::WarningEvent, this);
    }
    bool any() const noexcept { return !errors.empty() || !warnings.empty(); }
    /// The first few messages, errors first (a truncated file can report one per array), the
    /// pipeline's own ones only when there is nothing else.
    std::string summary() const {
        std::vector<std::string> all = errors;
        all.insert(all.end(), warnings.begin(), warnings.end());
        if (!std::all_of(all.begin(), all.end(), isPipelineMessage)) std::erase_if(all, isPipelineMessage);
        all.erase(std::unique(all.begin(), all.end()), all.end());
        if (all.size() > 3) {
            all.resize(3);
            all.push_back("...");
        }
        return joinList(all, "; ");
    }

    std::vector<std::string> errors, warnings;
};

/// While alive: VTK's global output window prints nothing and reports its errors and warnings
/// to `sink`, vtkLogger's stderr sink is off, and no other thread reads a field file.
class VtkQuiet {
public:
    explicit VtkQuiet(MessageSink* sink) : m_lock(mutex()), m_window(vtkOutputWindow::GetInstance()) {
        m_mode = m_window->GetDisplayMode();
        m_window->SetDisplayModeToNever();
        m_errorTag = m_window->AddObserver(vtkCommand::ErrorEvent, sink);
        m_warningTag = m_window->AddObserver(vtkCommand::WarningEvent, sink);
        m_verbosity = vtkLogger::GetCurrentVerbosityCutoff();
        vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
    }
    ~VtkQuiet() {
        vtkLogger::SetStderrVerbosity(m_verbosity);
        m_window->RemoveObserver(m_errorTag);
        m_window->RemoveObserver(m_warningTag);
        m_window->SetDisplayMode(m_mode);
    }
    VtkQuiet(const VtkQuiet&) = delete;
    VtkQuiet& operator=(const VtkQuiet&) = delete;

private:
    static std::mutex& mutex() {
        static std::mutex m;
        return m;
    }
    std::lock_guard<std::mutex> m_lock;
    vtkOutputWindow* m_window;
    int m_mode = vtkOutputWindow::DEFAULT;
    unsigned long m_errorTag = 0, m_warningTag = 0;
    vtkLogger::Verbosity m_verbosity = vtkLogger::VERBOSITY_WARNING;
};

// ---------------------------------------------------------------------------------------------
// File -> vtkDataSet

template <class Reader>
vtkSmartPointer<Reader> namedReader(const std::string& path) {
    auto reader = vtkSmartPointer<Reader>::New();
    reader->SetFileName(path.c_str());
    return reader;
}

/// The VTK reader for the file's extension; throws for an unknown one.
vtkSmartPointer<vtkAlgorithm> makeReader(const std::string& path, MessageSink* sink) {
    const std::string ext = lowerExtension(path);
    if (ext == ".vtk") {
        auto legacy = namedReader<vtkDataSetReader>(path);
        // By default a legacy reader keeps only the first SCALARS/VECTORS/... block of each kind.
        legacy->ReadAllScalarsOn();
        legacy->ReadAllVectorsOn();
        legacy->ReadAllNormalsOn();
        legacy->ReadAllTensorsOn();
        legacy->ReadAllColorScalarsOn();
        legacy->ReadAllTCoordsOn();
        legacy->ReadAllFieldsOn();
        return legacy;
    }
    vtkSmartPointer<vtkXMLReader> xml;
    if (ext == ".vtu") xml = namedReader<vtkXMLUnstructuredGridReader>(path);
    if (ext == ".vtr") xml = namedReader<vtkXMLRectilinearGridReader>(path);
    if (ext == ".vts") xml = namedReader<vtkXMLStructuredGridReader>(path);
    if (ext == ".vti") xml = namedReader<vtkXMLImageDataReader>(path);
    if (ext == ".vtp") xml = namedReader<vtkXMLPolyDataReader>(path);
    if (ext == ".vtm") xml = namedReader<vtkXMLMultiBlockDataReader>(path);
    if (!xml)
        throw FieldFileError(path + ": unknown field file type '" + ext +
                             "' (expected .vtk .vtu .vtr .vts .vti .vtp .vtm)");
    xml->SetReaderErrorObserver(sink);  // also passed on to a multiblock's block readers
    xml->SetParserErrorObserver(sink);
    return xml;
}

/// "TimeValue" [s] of a field data block (first tuple), NaN when absent or empty.
double timeValue(vtkDataObject* object) {
    vtkFieldData* fd = object ? object->GetFieldData() : nullptr;
    vtkDataArray* a = fd ? fd->GetArray("TimeValue") : nullptr;
    if (!a || a->GetNumberOfTuples() < 1) return std::numeric_limits<double>::quiet_NaN();
    return a->GetComponent(0, 0);
}

bool hasArray(vtkDataSet* ds, const std::string& name) {
    return ds->GetPointData()->GetAbstractArray(name.c_str()) ||
           ds->GetCellData()->GetAbstractArray(name.c_str());
}

/// A composite's children as (name, object) pairs (multiblocks and multipieces, as a .vtm has).
std::vector<std::pair<std::string, vtkDataObject*>> children(vtkDataObject* object) {
    std::vector<std::pair<std::string, vtkDataObject*>> out;
    const auto add = [&](vtkDataObject* child, vtkInformation* meta) {
        const char* name =
            meta && meta->Has(vtkCompositeDataSet::NAME()) ? meta->Get(vtkCompositeDataSet::NAME()) : nullptr;
        if (child) out.emplace_back(name ? name : "", child);
    };
    if (auto* mb = vtkMultiBlockDataSet::SafeDownCast(object)) {
        for (unsigned i = 0; i < mb->GetNumberOfBlocks(); ++i)
            add(mb->GetBlock(i), mb->HasMetaData(i) ? mb->GetMetaData(i) : nullptr);
    } else if (auto* mp = vtkMultiPieceDataSet::SafeDownCast(object)) {
        for (unsigned i = 0; i < mp->GetNumberOfPieces(); ++i)
            add(mp->GetPieceAsDataObject(i), mp->HasMetaData(i) ? mp->GetMetaData(i) : nullptr);
    }
    return out;
}

/// First non-empty dataset in the tree (depth first) that has the velocity array.
vtkDataSet* firstWithArray(vtkDataObject* object, const std::string& velocity) {
    if (auto* ds = vtkDataSet::SafeDownCast(object))
        return ds->GetNumberOfPoints() > 0 && hasArray(ds, velocity) ? ds : nullptr;
    for (const auto& [name, child] : children(object))
        if (vtkDataSet* found = firstWithArray(child, velocity)) return found;
    return nullptr;
}

/// The block named "internal" (foamToVTK's mesh), searched depth first; nullptr if none.
vtkDataObject* internalBlock(vtkDataObject* object) {
    for (const auto& [name, child] : children(object)) {
        if (name == "internal") return child;
        if (vtkDataObject* found = internalBlock(child)) return found;
    }
    return nullptr;
}

struct LoadedData {
    vtkSmartPointer<vtkDataSet> data;
    double time = std::numeric_limits<double>::quiet_NaN();  ///< [s]
};

/// The dataset of a multiblock file: its "internal" block (or the first dataset with the velocity
/// array inside it), else the first non-empty dataset with the velocity array.
vtkDataSet* pickBlock(vtkDataObject* root, const std::string& path, const std::string& velocity) {
    if (vtkDataObject* internal = internalBlock(root)) {
        if (auto* ds = vtkDataSet::SafeDownCast(internal)) return ds;
        if (vtkDataSet* ds = firstWithArray(internal, velocity)) return ds;
        throw FieldFileError(path + ": block 'internal' holds no dataset with the array '" + velocity + "'");
    }
    if (vtkDataSet* ds = firstWithArray(root, velocity)) return ds;
    throw FieldFileError(path + ": no block of the multiblock file has points and the array '" + velocity +
                         "'");
}

/// Phrases of VTK's messages when a file ends early (legacy ASCII/binary, XML structure, XML data).
const std::vector<const char*> kTruncationCues = {
    "rror reading", "EOF", "end of file", "Premature", "not long enough", "no element found", "Read 0 of"};

/// Runs VTK's reader on the file and returns the dataset to convert, with its TimeValue.
LoadedData loadDataSet(const std::string& path, const std::string& velocity) {
    std::error_code ec;
    if (!fs::exists(path, ec)) throw FieldFileError(path + ": no such file");
    if (fs::is_directory(path, ec)) throw FieldFileError(path + ": is a folder, not a field file");

    vtkNew<MessageSink> sink;
    const VtkQuiet quiet(sink);
    vtkSmartPointer<vtkAlgorithm> reader = makeReader(path, sink);
    sink->observe(reader);
    sink->observe(reader->GetExecutive());
    try {
        reader->Update();
    } catch (const std::bad_alloc&) {
        throw FieldFileError(path + ": not a readable VTK file (its sizes exceed the memory)");
    }
    // Warnings count too: the legacy reader reports a short ASCII array ("Error reading ascii data")
    // as a warning and keeps the array at its declared size, the missing values uninitialised.
    if (sink->any() || reader->GetErrorCode() != 0) {
        const std::string why =
            sink->any() ? sink->summary() : "VTK error code " + std::to_string(reader->GetErrorCode());
        const bool cut = std::any_of(kTruncationCues.begin(), kTruncationCues.end(),
                                     [&](const char* cue) { return why.find(cue) != std::string::npos; });
        throw FieldFileError(
            path + (cut ? ": truncated or corrupt VTK file (" : ": not a readable VTK file (") + why + ")");
    }
    vtkDataObject* root = reader->GetOutputDataObject(0);
    if (!root) throw FieldFileError(path + ": not a readable VTK file (the reader produced no data)");
    vtkDataSet* ds = vtkDataSet::SafeDownCast(root);
    if (!ds) ds = pickBlock(root, path, velocity);
    LoadedData out;
    out.data = ds;  // keeps the dataset alive after the reader (and the other blocks) go
    out.time = timeValue(ds);
    if (std::isnan(out.time)) out.time = timeValue(root);
    return out;
}

// ---------------------------------------------------------------------------------------------
// Arrays

std::string arrayNames(vtkFieldData* fd) {
    std::vector<std::string> names;
    for (int i = 0; i < fd->GetNumberOfArrays(); ++i) {
        const char* name = fd->GetArrayName(i);
        names.emplace_back(name ? name : "(unnamed)");
    }
    return names.empty() ? "none" : joinList(names);
}

enum class Where { Point, Cell };

/// Where the array is taken from, as options.data says; throws naming what the file has.
Where locateArray(vtkDataSet* ds, const std::string& path, const std::string& name, const std::string& mode) {
    const bool inPoints = ds->GetPointData()->GetAbstractArray(name.c_str()) != nullptr;
    const bool inCells = ds->GetCellData()->GetAbstractArray(name.c_str()) != nullptr;
    if (mode != "auto" && mode != "point" && mode != "cell")
        throw FieldFileError(path + ": data must be auto, point or cell, got '" + mode + "'");
    if ((mode == "auto" || mode == "point") && inPoints) return Where::Point;
    if ((mode == "auto" || mode == "cell") && inCells) return Where::Cell;
    const std::string kind = mode == "auto" ? "" : mode + " ";
    const bool none =
        ds->GetPointData()->GetNumberOfArrays() == 0 && ds->GetCellData()->GetNumberOfArrays() == 0;
    throw FieldFileError(path + ": no " + kind + "array '" + name + "' (point arrays: " +
                         arrayNames(ds->GetPointData()) + "; cell arrays: " + arrayNames(ds->GetCellData()) +
                         ")" + (none ? "; the file has no data arrays at all (truncated?)" : ""));
}

/// The numeric array `name` of `attributes`, checked for its component and tuple counts.
vtkDataArray* checkedArray(vtkDataSetAttributes* attributes, const std::string& path, const std::string& name,
                           int minComponents, int maxComponents, vtkIdType tuples, const char* perWhat) {
    vtkDataArray* a = attributes->GetArray(name.c_str());
    if (!a) throw FieldFileError(path + ": array '" + name + "' is not numeric");
    const int nc = a->GetNumberOfComponents();
    if (nc < minComponents || nc > maxComponents)
        throw FieldFileError(path + ": array '" + name + "' has " + std::to_string(nc) +
                             " component(s), expected " +
                             (minComponents == maxComponents
                                  ? std::to_string(minComponents)
                                  : std::to_string(minComponents) + " or " + std::to_string(maxComponents)));
    if (a->GetNumberOfTuples() != tuples)
        throw FieldFileError(path + ": array '" + name + "' has " + std::to_string(a->GetNumberOfTuples()) +
                             " tuples for " + std::to_string(tuples) + " " + perWhat + " (truncated file?)");
    return a;
}

/// Averages the listed cell arrays to the points (vtkCellDataToPointData) on a copy of the
/// structure that carries only those arrays, so the output's point data holds exactly them.
vtkSmartPointer<vtkDataSet> cellArraysToPoints(vtkDataSet* ds, const std::vector<vtkDataArray*>& arrays,
                                               const std::string& path) {
    vtkSmartPointer<vtkDataSet> shell = vtkSmartPointer<vtkDataSet>::Take(ds->NewInstance());
    shell->CopyStructure(ds);  // shallow: points and cells are shared
    for (vtkDataArray* a : arrays) shell->GetCellData()->AddArray(a);
    vtkNew<vtkCellDataToPointData> filter;
    filter->SetInputData(shell);
    filter->PassCellDataOff();
    vtkNew<MessageSink> sink;
    {
        const VtkQuiet quiet(sink);
        sink->observe(filter);
        filter->Update();
    }
    if (sink->any() || !filter->GetOutput())
        throw FieldFileError(path + ": cell data could not be averaged to the points (" + sink->summary() +
                             ")");
    return filter->GetOutput();
}

/// Throws when a value of `a` (one tuple per point) is NaN or infinite, naming the point.
void checkFinite(vtkDataArray* a, vtkDataSet* ds, const std::string& path, const std::string& name) {
    const int nc = a->GetNumberOfComponents();
    for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
        for (int c = 0; c < nc; ++c) {
            const double v = a->GetComponent(i, c);
            if (std::isfinite(v)) continue;
            double q[3];
            ds->GetPoint(i, q);
            std::ostringstream msg;
            msg << path << ": array '" << name << "' has a non-finite value (" << v << ") at node " << i
                << " (x = " << q[0] << ", y = " << q[1] << ", z = " << q[2] << ")";
            throw FieldFileError(msg.str());
        }
}

/// The velocity and (optionally) pressure arrays as point data, checked; the dataset they refer to
/// (the input, or the converted copy when an array came from cell data) is kept alive in `holder`.
struct PointArrays {
    vtkSmartPointer<vtkDataSet> holder;
    vtkSmartPointer<vtkDataArray> velocity, pressure;
};

PointArrays pointArrays(vtkDataSet* ds, const std::string& path, const FieldReadOptions& o) {
    struct Request {
        std::string name;
        int minComponents, maxComponents;
        Where where;
    };
    std::vector<Request> requests = {{o.velocityArray, 2, 3, locateArray(ds, path, o.velocityArray, o.data)}};
    if (o.readPressure)
        requests.push_back({o.pressureArray, 1, 1, locateArray(ds, path, o.pressureArray, o.data)});

    std::vector<vtkDataArray*> fromCells;
    for (const Request& r : requests)
        if (r.where == Where::Cell)
            fromCells.push_back(checkedArray(ds->GetCellData(), path, r.name, r.minComponents,
                                             r.maxComponents, ds->GetNumberOfCells(), "cells"));
    vtkSmartPointer<vtkDataSet> converted =
        fromCells.empty() ? nullptr : cellArraysToPoints(ds, fromCells, path);

    PointArrays out;
    out.holder = converted ? converted : vtkSmartPointer<vtkDataSet>(ds);
    for (std::size_t k = 0; k < requests.size(); ++k) {
        const Request& r = requests[k];
        vtkDataSet* source = r.where == Where::Cell ? converted.Get() : ds;
        vtkDataArray* a = checkedArray(source->GetPointData(), path, r.name, r.minComponents, r.maxComponents,
                                       ds->GetNumberOfPoints(), "points");
        checkFinite(a, ds, path, r.name);
        (k == 0 ? out.velocity : out.pressure) = a;
    }
    return out;
}

// ---------------------------------------------------------------------------------------------
// Reduction to the DEM plane

/// Which points become which node; `nodePoint` is the point each node takes its values from.
struct NodeMap {
    std::vector<std::uint32_t> pointToNode;  ///< kDropped for points not kept
    std::vector<vtkIdType> nodePoint;
    double depth = 0;  ///< [m]
};

/// Number of z levels (clusters closer than tol) among the points, for the 3D error message.
std::size_t countZLevels(vtkDataSet* ds, double tol) {
    std::vector<double> z(static_cast<std::size_t>(ds->GetNumberOfPoints()));
    double q[3];
    for (std::size_t i = 0; i < z.size(); ++i) {
        ds->GetPoint(static_cast<vtkIdType>(i), q);
        z[i] = q[2];
    }
    std::sort(z.begin(), z.end());
    std::size_t levels = 1;
    for (std::size_t i = 1; i < z.size(); ++i) levels += z[i] - z[i - 1] > tol;
    return levels;
}

/// z collapse and (x, y) merge (cfddem spec 5.5 [R]); see readFlowField in the header.
NodeMap collapseToPlane(vtkDataSet* ds, const std::string& path) {
    double b[6];
    ds->GetBounds(b);
    const double extent = std::max({b[1] - b[0], b[3] - b[2], b[5] - b[4]});
    const double tol = std::max(1e-9 * extent, 1e-12);  // [m]
    const bool twoLevels = b[5] - b[4] > tol;
    const auto n = static_cast<std::size_t>(ds->GetNumberOfPoints());

    NodeMap map;
    map.depth = twoLevels ? b[5] - b[4] : 0.0;
    map.pointToNode.assign(n, kDropped);
    std::unordered_map<std::uint64_t, std::uint32_t> cellToNode;  // hash cell (one tol wide) -> node
    cellToNode.reserve(twoLevels ? n / 2 : n);
    const auto cellOf = [&](double v, double lo) {
        return static_cast<std::int64_t>(std::floor((v - lo) / tol));
    };
    const auto key = [](std::int64_t ix, std::int64_t iy) {
        return (static_cast<std::uint64_t>(ix) << 32) | static_cast<std::uint64_t>(iy);
    };
    double q[3];
    for (std::size_t i = 0; i < n; ++i) {
        ds->GetPoint(static_cast<vtkIdType>(i), q);
        if (twoLevels && std::abs(q[2] - b[4]) > tol) {
            if (std::abs(q[2] - b[5]) <= tol) continue;  // the upper layer of an extruded 2D mesh
            throw FieldFileError(path + ": is a 3D field (" + std::to_string(countZLevels(ds, tol)) +
                                 " z levels); granulab's DEM is 2D");
        }
        const std::int64_t ix = cellOf(q[0], b[0]), iy = cellOf(q[1], b[2]);
        std::uint32_t node = kDropped;
        for (std::int64_t dx = -1; dx <= 1 && node == kDropped; ++dx)
            for (std::int64_t dy = -1; dy <= 1 && node == kDropped; ++dy) {
                if (ix + dx < 0 || iy + dy < 0) continue;
                const auto it = cellToNode.find(key(ix + dx, iy + dy));
                if (it == cellToNode.end()) continue;
                double r[3];
                ds->GetPoint(map.nodePoint[it->second], r);
                if (std::abs(r[0] - q[0]) <= tol && std::abs(r[1] - q[1]) <= tol) node = it->second;
            }
        if (node == kDropped) {
            node = static_cast<std::uint32_t>(map.nodePoint.size());
            map.nodePoint.push_back(static_cast<vtkIdType>(i));
            cellToNode.emplace(key(ix, iy), node);
        }
        map.pointToNode[i] = node;
    }
    return map;
}

/// Sorts a cell's nodes counter-clockwise by their angle about the centroid.
void orderCounterClockwise(std::vector<std::uint32_t>& nodes, const fluid::FlowField& f) {
    double cx = 0, cy = 0;
    for (std::uint32_t k : nodes) cx += f.x[k], cy += f.y[k];
    cx /= static_cast<double>(nodes.size());
    cy /= static_cast<double>(nodes.size());
    std::vector<std::pair<double, std::uint32_t>> byAngle;
    for (std::uint32_t k : nodes) byAngle.emplace_back(std::atan2(f.y[k] - cy, f.x[k] - cx), k);
    std::sort(byAngle.begin(), byAngle.end());
    for (std::size_t i = 0; i < nodes.size(); ++i) nodes[i] = byAngle[i].second;
}

/// Each VTK cell's surviving distinct nodes, if 3 or more, as one 2D cell.
void addCells(vtkDataSet* ds, const NodeMap& map, fluid::FlowField& f) {
    vtkNew<vtkIdList> ids;
    std::vector<std::uint32_t> nodes;
    f.cellOffsets.reserve(static_cast<std::size_t>(ds->GetNumberOfCells()) + 1);
    f.cellOffsets.push_back(0);
    for (vtkIdType c = 0; c < ds->GetNumberOfCells(); ++c) {
        ds->GetCellPoints(c, ids);
        nodes.clear();
        for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k) {
            const std::uint32_t node = map.pointToNode[static_cast<std::size_t>(ids->GetId(k))];
            if (node != kDropped && std::find(nodes.begin(), nodes.end(), node) == nodes.end())
                nodes.push_back(node);
        }
        if (nodes.size() < 3) continue;
        orderCounterClockwise(nodes, f);
        f.cellNodes.insert(f.cellNodes.end(), nodes.begin(), nodes.end());
        f.cellOffsets.push_back(static_cast<std::uint32_t>(f.cellNodes.size()));
    }
    if (f.cellOffsets.size() < 2) f.cellOffsets.clear();
    f.cellOffsets.shrink_to_fit();
    f.cellNodes.shrink_to_fit();
}

// ---------------------------------------------------------------------------------------------
// Collections

/// The last run of digits in a file name's stem, without leading zeros ("" if none).
std::string lastInteger(const fs::path& p) {
    const std::string stem = p.stem().string();
    const std::size_t end = stem.find_last_of("0123456789");
    if (end == std::string::npos) return "";
    std::size_t begin = end;
    while (begin > 0 && std::isdigit(static_cast<unsigned char>(stem[begin - 1]))) --begin;
    const std::size_t nonZero = std::min(stem.find_first_not_of('0', begin), end);
    return stem.substr(nonZero, end + 1 - nonZero);
}

/// Numeric order of the last integers (as digit strings, so any length works), then by name.
bool numericBefore(const fs::path& a, const fs::path& b) {
    const std::string na = lastInteger(a), nb = lastInteger(b);
    if (na.size() != nb.size()) return na.size() < nb.size();
    if (na != nb) return na < nb;
    return a.filename() < b.filename();
}

FieldFile listedFile(const fs::path& collection, const std::string& name, double time) {
    const fs::path file = (collection.parent_path() / name).lexically_normal();
    std::error_code ec;
    if (!fs::is_regular_file(file, ec))
        throw FieldFileError(collection.string() + ": listed file '" + name + "' does not exist (" +
                             file.string() + ")");
    return {file.string(), time};
}

std::vector<FieldFile> readPvdCollection(const fs::path& pvd) {
    const std::string path = pvd.string();
    vtkNew<MessageSink> sink;
    vtkSmartPointer<vtkXMLDataElement> root;
    {
        const VtkQuiet quiet(sink);
        root.TakeReference(vtkXMLUtilities::ReadElementFromFile(path.c_str()));  // nullptr if malformed
    }
    if (!root) throw FieldFileError(path + ": malformed .pvd collection (" + sink->summary() + ")");
    const char* type = root->GetAttribute("type");
    vtkXMLDataElement* collection = root->FindNestedElementWithName("Collection");
    if (std::string(root->GetName()) != "VTKFile" || !type || std::string(type) != "Collection" ||
        !collection)
        throw FieldFileError(path +
                             ": malformed .pvd collection (no <VTKFile type=\"Collection\"><Collection>)");
    std::vector<FieldFile> out;
    for (int i = 0; i < collection->GetNumberOfNestedElements(); ++i) {
        vtkXMLDataElement* e = collection->GetNestedElement(i);
        if (std::string(e->GetName()) != "DataSet") continue;
        const char* file = e->GetAttribute("file");
        if (!file) throw FieldFileError(path + ": malformed .pvd collection (a DataSet without file)");
        double time = std::numeric_limits<double>::quiet_NaN();
        if (const char* t = e->GetAttribute("timestep")) {
            char* end = nullptr;
            time = std::strtod(t, &end);
            if (end == t || *end != '\0')
                throw FieldFileError(path + ": malformed .pvd collection (timestep '" + t + "')");
        }
        out.push_back(listedFile(pvd, file, time));
    }
    if (out.empty()) throw FieldFileError(path + ": malformed .pvd collection (no DataSet)");
    return out;
}

std::vector<FieldFile> readSeriesCollection(const fs::path& series) {
    const std::string path = series.string();
    nlohmann::json doc;
    try {
        std::ifstream in(series);
        doc = nlohmann::json::parse(in);
    } catch (const nlohmann::json::exception& e) {
        throw FieldFileError(path + ": malformed .series file (" + e.what() + ")");
    }
    const auto bad = [&](const std::string& why) {
        return FieldFileError(path + ": malformed .series file (" + why + ")");
    };
    if (!doc.is_object() || !doc.contains("files") || !doc["files"].is_array())
        throw bad("expected {\"file-series-version\": \"1.0\", \"files\": [...]}");
    std::vector<FieldFile> out;
    for (const nlohmann::json& f : doc["files"]) {
        if (!f.is_object() || !f.contains("name") || !f["name"].is_string())
            throw bad("an entry of files has no string name");
        double time = std::numeric_limits<double>::quiet_NaN();
        if (f.contains("time")) {
            if (!f["time"].is_number())
                throw bad("time of '" + f["name"].get<std::string>() + "' is not a number");
            time = f["time"].get<double>();
        }
        out.push_back(listedFile(series, f["name"].get<std::string>(), time));
    }
    if (out.empty()) throw bad("files is empty");
    return out;
}

std::vector<FieldFile> listFolder(const fs::path& folder) {
    std::vector<fs::path> collections, data;
    for (const fs::directory_entry& e : fs::directory_iterator(folder)) {
        if (!e.is_regular_file()) continue;
        const std::string ext = lowerExtension(e.path());
        if (ext == ".series" || ext == ".pvd") collections.push_back(e.path());
        if (isDataFile(e.path())) data.push_back(e.path());
    }
    if (collections.size() == 1) return listFieldFiles(collections.front().string());
    if (collections.size() > 1) {
        std::vector<std::string> names;
        for (const fs::path& p : collections) names.push_back(p.filename().string());
        std::sort(names.begin(), names.end());
        throw FieldFileError(folder.string() + ": holds several collections (" + joinList(names) +
                             "); name one of them");
    }
    if (data.empty())
        throw FieldFileError(folder.string() +
                             ": no field files (.vtk .vtu .vtr .vts .vti .vtm) in the folder");
    std::sort(data.begin(), data.end(), numericBefore);
    std::vector<FieldFile> out;
    for (const fs::path& p : data) out.push_back({p.string(), std::numeric_limits<double>::quiet_NaN()});
    return out;
}

/// The nodes' coordinates [m] and values from their representative points.
void fillNodes(vtkDataSet* ds, const NodeMap& map, const PointArrays& arrays, fluid::FlowField& f) {
    const std::size_t nodes = map.nodePoint.size();
    f.x.resize(nodes);
    f.y.resize(nodes);
    f.ux.resize(nodes);
    f.uy.resize(nodes);
    if (arrays.pressure) f.p.resize(nodes);
    double q[3];
    for (std::size_t k = 0; k < nodes; ++k) {
        const vtkIdType i = map.nodePoint[k];
        ds->GetPoint(i, q);
        f.x[k] = q[0];
        f.y[k] = q[1];
        f.ux[k] = arrays.velocity->GetComponent(i, 0);
        f.uy[k] = arrays.velocity->GetComponent(i, 1);
        if (arrays.pressure) f.p[k] = arrays.pressure->GetComponent(i, 0);
    }
}

}  // namespace

fluid::FlowField readFlowField(const std::string& path, const FieldReadOptions& options) {
    const LoadedData loaded = loadDataSet(path, options.velocityArray);
    vtkDataSet* ds = loaded.data;
    if (ds->GetNumberOfPoints() <= 0) throw FieldFileError(path + ": the dataset has no points");
    if (static_cast<std::uint64_t>(ds->GetNumberOfPoints()) >= kDropped)
        throw FieldFileError(path + ": too many points (" + std::to_string(ds->GetNumberOfPoints()) + ")");

    fluid::FlowField f;
    f.source = path;
    f.time = loaded.time;
    const NodeMap map = [&] {
        const PointArrays arrays = pointArrays(ds, path, options);  // a converted copy lives only here
        NodeMap m = collapseToPlane(ds, path);
        fillNodes(ds, m, arrays, f);
        return m;
    }();
    f.depth = map.depth;
    addCells(ds, map, f);
    return f;
}

std::vector<FieldFile> listFieldFiles(const std::string& entry) {
    const fs::path p(entry);
    std::error_code ec;
    if (!fs::exists(p, ec)) throw FieldFileError(entry + ": no such file or folder");
    if (fs::is_directory(p, ec)) return listFolder(p);
    const std::string ext = lowerExtension(p);
    if (ext == ".pvd") return readPvdCollection(p);
    if (ext == ".series") return readSeriesCollection(p);
    if (!isDataFile(p))
        throw FieldFileError(
            entry + ": not a field file (.vtk .vtu .vtr .vts .vti .vtm) or collection (.pvd .series)");
    return {{entry, std::numeric_limits<double>::quiet_NaN()}};
}

}  // namespace granulab::io
