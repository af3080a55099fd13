// SPDX-License-Identifier: MIT
// Generator scripts as gsi input (io/gsi_script.hpp; gc2d spec 9.8).
#include "io/gsi_script.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cstring>
#include <sstream>

#include "core/ascii_case.hpp"
#include "core/error.hpp"
#include "io/gsi_scene.hpp"
#include "io/gsi_syntax.hpp"

namespace granulab::io {

namespace {

/// Reads everything from `fd` until end of file.
std::string drain(int fd) {
    std::string out;
    char buffer[1 << 16];
    for (;;) {
        const ssize_t n = read(fd, buffer, sizeof buffer);
        if (n > 0) {
            out.append(buffer, static_cast<std::size_t>(n));
        } else if (n == 0 || errno != EINTR) {
            return out;
        }
    }
}

struct ScriptResult {
    int status = 0;  ///< exit status, or 128 + signal
    std::string out, err;
};

/// Runs argv[0] with argv (no shell), stdout and stderr captured (stderr to a temporary file, so
/// that neither pipe can fill up and block the script).
ScriptResult runProgram(const std::vector<std::string>& argv, const std::string& path) {
    int outPipe[2];
    if (pipe(outPipe) != 0)
        throw SceneError(
            makeDiagnostic(path, 0, "", fmt::format("cannot run the script: {}", std::strerror(errno))));
    char errName[] = "/tmp/granulab-script-XXXXXX";
    const int errFd = mkstemp(errName);
    if (errFd >= 0) unlink(errName);
    const pid_t pid = fork();
    if (pid < 0)
        throw SceneError(
            makeDiagnostic(path, 0, "", fmt::format("cannot run the script: {}", std::strerror(errno))));
    if (pid == 0) {
        dup2(outPipe[1], STDOUT_FILENO);
        if (errFd >= 0) dup2(errFd, STDERR_FILENO);
        close(outPipe[0]);
        close(outPipe[1]);
        std::vector<char*> args;
        for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
        args.push_back(nullptr);
        execvp(args[0], args.data());
        const std::string msg = fmt::format("cannot execute {}: {}\n", argv[0], std::strerror(errno));
        (void)!write(STDERR_FILENO, msg.data(), msg.size());
        _exit(127);
    }
    close(outPipe[1]);
    ScriptResult r;
    r.out = drain(outPipe[0]);
    close(outPipe[0]);
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    r.status = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    if (errFd >= 0) {
        lseek(errFd, 0, SEEK_SET);
        r.err = drain(errFd);
        close(errFd);
    }
    return r;
}

}  // namespace

bool isGsiScript(const std::string& path) {
    const std::string l = asciiLower(path);
    if (l.ends_with(".gsi.pl") || l.ends_with(".gsi.py") || l.ends_with(".gsi.sh")) return true;
    if (l.ends_with(".toml") || isGsiPath(path)) return false;
    struct stat st {};
    return stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode) && (st.st_mode & 0111) != 0 &&
           l.find(".gsi") != std::string::npos;
}

std::vector<std::string> splitScriptArgs(const std::string& text) {
    std::vector<std::string> words;
    std::istringstream in(text);
    std::string w;
    while (in >> w) words.push_back(w);
    return words;
}

model::SceneDef readGsiScript(const std::string& path, const std::vector<std::string>& args, bool allowed) {
    if (!allowed)
        throw SceneError(makeDiagnostic(
            path, 0, "",
            "is a generator script: granulab runs it and reads its output as gsi only when you allow it "
            "with --allow-script (it runs with your rights; read it first); its arguments go after -P, "
            "e.g. granulab run --allow-script " +
                path + " -P \"0.1 20\""));
    struct stat st {};
    if (stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode))
        throw SceneError(
            makeDiagnostic(path, 0, "", "cannot open the generator script (missing or not a file)"));
    std::vector<std::string> argv;
    const std::string l = asciiLower(path);
    const std::string self = path.find('/') == std::string::npos ? "./" + path : path;
    if (l.ends_with(".pl"))
        argv = {"perl", path};
    else if (l.ends_with(".py") && (st.st_mode & 0111) == 0)
        argv = {"python3", path};
    else if (l.ends_with(".sh") && (st.st_mode & 0111) == 0)
        argv = {"sh", path};
    else
        argv = {self};
    argv.insert(argv.end(), args.begin(), args.end());
    const ScriptResult r = runProgram(argv, path);
    if (r.status != 0) {
        std::string err = r.err.size() > 2000 ? "..." + r.err.substr(r.err.size() - 2000) : r.err;
        while (!err.empty() && (err.back() == '\n' || err.back() == '\r')) err.pop_back();
        throw SceneError(makeDiagnostic(path, 0, "",
                                        fmt::format("the generator script failed (exit status {}){}{}",
                                                    r.status, err.empty() ? "" : ":\n", err)));
    }
    // Errors name lines of the generated text, as gc2d's did.
    return gsiToScene(parseGsi(r.out, path + " (output)"));
}

}  // namespace granulab::io
