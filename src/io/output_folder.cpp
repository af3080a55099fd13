// SPDX-License-Identifier: MIT
// Run outputs of a folder (io/output_folder.hpp). The lists below are the files and folders the
// writers of app/ and io/ create; a new output file or folder is added here too.
#include "io/output_folder.hpp"

#include <algorithm>
#include <array>
#include <filesystem>
#include <stdexcept>
#include <string_view>
#include <system_error>

namespace granulab::io {

namespace fs = std::filesystem;

namespace {

constexpr std::array<std::string_view, 6> kFiles = {"summary.json",   "series.csv",    "final.csv",
                                                    "checkpoint.bin", "snapshots.pvd", "theory.csv"};
constexpr std::array<std::string_view, 3> kFolders = {"vtk", "png", "analysis"};
/// What the writers put into those folders (snapshots, pictures, analysis tables and summaries).
constexpr std::array<std::string_view, 5> kFolderKinds = {".vtp", ".png", ".csv", ".json", ".tmp"};
/// gc2d's files (output.gc2d; gc2d spec 9.1), named <basename>[.NNNN].<ext> after the scene.
constexpr std::array<std::string_view, 9> kGc2dKinds = {".ggf", ".gff", ".gpf", ".gtf", ".gpl",
                                                        ".glk", ".ps",  ".gso", ".gco"};

bool isRunFile(const std::string& name) {
    std::string_view n = name;
    for (const auto f : kFiles)
        if (n == f || (n.size() == f.size() + 4 && n.starts_with(f) && n.ends_with(".tmp"))) return true;
    if (n.ends_with(".tmp")) n.remove_suffix(4);  // an atomic write's leftover
    for (const auto ext : kGc2dKinds)
        if (n.size() > ext.size() && n.ends_with(ext)) return true;
    return false;
}

bool isRunFolder(const std::string& name) {
    return std::find(kFolders.begin(), kFolders.end(), name) != kFolders.end();
}

void removeOrThrow(const fs::path& p) {
    std::error_code ec;
    fs::remove(p, ec);
    if (ec) throw std::runtime_error("cannot remove " + p.string() + ": " + ec.message());
}

}  // namespace

std::vector<std::string> runOutputsIn(const std::string& dir) {
    std::vector<std::string> found;
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) return found;
    for (const auto& entry : fs::directory_iterator(dir, ec)) {
        const std::string name = entry.path().filename().string();
        if (entry.is_directory(ec) ? isRunFolder(name) : isRunFile(name))
            found.push_back(entry.is_directory(ec) ? name + "/" : name);
    }
    std::sort(found.begin(), found.end());
    return found;
}

void removeRunOutputs(const std::string& dir) {
    for (const std::string& name : runOutputsIn(dir)) {
        if (!name.ends_with("/")) {
            removeOrThrow(fs::path(dir) / name);
            continue;
        }
        const fs::path folder = fs::path(dir) / name.substr(0, name.size() - 1);
        std::vector<fs::path> ours;  // collected first: no removal while the folder is listed
        std::error_code ec;
        for (const auto& entry : fs::directory_iterator(folder, ec))
            if (entry.is_regular_file(ec) &&
                std::find(kFolderKinds.begin(), kFolderKinds.end(), entry.path().extension().string()) !=
                    kFolderKinds.end())
                ours.push_back(entry.path());
        for (const auto& p : ours) removeOrThrow(p);
        fs::remove(folder, ec);  // only when empty: a file the user put there keeps it
    }
}

}  // namespace granulab::io
