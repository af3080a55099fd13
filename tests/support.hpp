// SPDX-License-Identifier: MIT
// Test helpers: build a World from a TOML string through the real reader/validator, run the
// granulab binary, temporary folders.
#pragma once
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "app/dem/dem_engine.hpp"
#include "dem/setup.hpp"
#include "io/scene_reader.hpp"
#include "model/material_names.hpp"
#include "support/scene.hpp"

namespace granulab::test {

inline dem::World makeWorldFromToml(const std::string& toml,
                                    const std::vector<io::Override>& overrides = {}) {
    const model::SceneDef scene = readSceneText(toml, "test.toml", overrides);
    const dem::PreparedScene v = app::checkAndPrepareDem(scene);
    dem::World w = dem::makeWorld(scene, v.initial, v.fields);
    w.initialize();
    return w;
}

/// Fresh folder per test (test name + pid: safe under ctest -j and parallel build trees),
/// removed again at the end of the test.
struct ScratchDir {
    std::filesystem::path path;
    ScratchDir() {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        make(std::string(info->test_suite_name()) + "_" + info->name());
    }
    /// Outside a test body (SetUpTestSuite), where there is no current test to name the folder.
    explicit ScratchDir(const std::string& name) { make(name); }
    ~ScratchDir() {
        std::error_code ec;
        std::filesystem::remove_all(path, ec);
    }
    ScratchDir(const ScratchDir&) = delete;
    void make(const std::string& name) {
        path =
            std::filesystem::temp_directory_path() / ("granulab_" + name + "_" + std::to_string(::getpid()));
        std::filesystem::remove_all(path);
        std::filesystem::create_directories(path);
    }
    ScratchDir& operator=(const ScratchDir&) = delete;
};

/// `s` with every `from` replaced by `to`.
inline std::string replaceAll(std::string s, const std::string& from, const std::string& to) {
    for (std::size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size()))
        s.replace(at, from.size(), to);
    return s;
}

inline void writeText(const std::filesystem::path& path, const std::string& text) {
    std::ofstream out(path);
    out << text;
}

/// A CSV file (final.csv, series.csv) as rows of fields keyed by the header names; `header` gets
/// the column names in order.
inline std::vector<std::map<std::string, std::string>> readCsv(const std::filesystem::path& p,
                                                               std::vector<std::string>& header) {
    std::ifstream in(p);
    std::string line;
    const auto split = [](const std::string& l) {
        std::vector<std::string> out;
        std::stringstream ss(l);
        std::string cell;
        while (std::getline(ss, cell, ',')) out.push_back(cell);
        return out;
    };
    std::getline(in, line);
    header = split(line);
    std::vector<std::map<std::string, std::string>> rows;
    while (std::getline(in, line)) {
        const auto cells = split(line);
        EXPECT_EQ(cells.size(), header.size()) << line;
        std::map<std::string, std::string> row;
        for (std::size_t k = 0; k < cells.size() && k < header.size(); ++k) row[header[k]] = cells[k];
        rows.push_back(std::move(row));
    }
    return rows;
}

inline std::string readText(const std::filesystem::path& path) {
    std::ifstream in(path);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

struct CommandResult {
    int status = -1;
    std::string output;  ///< stdout and stderr together
};

/// Runs the granulab binary with `args` (a shell fragment); with `timeoutSeconds` > 0 it is
/// killed after that long (status 124: a hang fails the test instead of stalling the suite).
inline CommandResult runGranulab(const std::string& args, const std::filesystem::path& workDir,
                                 int timeoutSeconds = 0) {
    const auto log = workDir / "command.log";
    const std::string limit = timeoutSeconds > 0 ? "timeout " + std::to_string(timeoutSeconds) + " " : "";
    const std::string cmd = std::string("cd '") + workDir.string() + "' && " + limit + "'" + GRANULAB_BINARY +
                            "' " + args + " > '" + log.string() + "' 2>&1";
    const int raw = std::system(cmd.c_str());
    CommandResult r;
    r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    r.output = readText(log);
    return r;
}

}  // namespace granulab::test
