// SPDX-License-Identifier: MIT
// Signal handlers, hang alarm and silenced output of the fuzz harness (tests/fuzz/fuzz_guard.hpp).
// The handlers use only async-signal-safe calls (open, write, close, sigaction, raise, _exit) on
// buffers prepared by beginInput.
#include "fuzz_guard.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/time.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#if defined(__SANITIZE_ADDRESS__)
#include <sanitizer/common_interface_defs.h>
#endif

namespace granulab::fuzz {

namespace {

int g_out = STDOUT_FILENO;  ///< the harness's stdout and stderr after silenceEngines
int g_err = STDERR_FILENO;
unsigned g_hangSeconds = 20;
const char* g_text = nullptr;  ///< the input being run
std::size_t g_length = 0;
const char* g_stage = "";
bool g_save = false;
char g_crashPath[4096];
char g_hangPath[4096];
char g_origin[1024];

constexpr int kFatalSignals[] = {SIGSEGV, SIGBUS, SIGILL, SIGFPE, SIGABRT};
struct sigaction g_previous[sizeof(kFatalSignals) / sizeof(int)];

std::uint64_t fnv1a(const std::string& s) {
    std::uint64_t h = 0xcbf29ce484222325ULL;
    for (const unsigned char c : s) h = (h ^ c) * 0x100000001b3ULL;
    return h;
}

void copyString(char* to, std::size_t size, const std::string& from) {
    const std::size_t n = std::min(size - 1, from.size());
    std::memcpy(to, from.data(), n);
    to[n] = '\0';
}

// ---- async-signal-safe helpers ---------------------------------------------------------------
void put(int fd, const char* s) {
    if (write(fd, s, std::strlen(s)) < 0) return;
}

void putNumber(int fd, std::uint64_t v) {
    char buf[24];
    int i = 23;
    buf[i] = '\0';
    do {
        buf[--i] = static_cast<char>('0' + v % 10);
        v /= 10;
    } while (v > 0 && i > 0);
    put(fd, buf + i);
}

void putSummary(int fd, std::uint64_t crashes, std::uint64_t hangs) {
    const Counters& c = counters();
    put(fd, "fuzz-summary mutants=");
    putNumber(fd, c.mutants);
    put(fd, " ok=");
    putNumber(fd, c.ok);
    put(fd, " bad_input=");
    putNumber(fd, c.badInput);
    put(fd, " unstable=");
    putNumber(fd, c.unstable);
    put(fd, " exceptions=");
    putNumber(fd, c.exceptions);
    put(fd, " crashes=");
    putNumber(fd, crashes);
    put(fd, " hangs=");
    putNumber(fd, hangs);
    put(fd, "\n");
}

/// Writes the current input to `path` and a note beside it (path + ".txt").
void saveCurrent(const char* path, const char* what) {
    if (!g_save || g_text == nullptr) return;
    int fd = open(path, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) {
        if (write(fd, g_text, g_length) < 0) put(g_err, "fuzz: could not write the input\n");
        close(fd);
    }
    char note[4200];
    const std::size_t n = std::strlen(path);
    if (n + 5 >= sizeof(note)) return;
    std::memcpy(note, path, n);
    std::memcpy(note + n, ".txt", 5);
    fd = open(note, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd < 0) return;
    put(fd, what);
    put(fd, " in stage ");
    put(fd, g_stage);
    put(fd, "\norigin: ");
    put(fd, g_origin);
    put(fd, "\n");
    close(fd);
}

void announce(const char* what, const char* path) {
    put(g_err, "\nfuzz: ");
    put(g_err, what);
    put(g_err, " in stage ");
    put(g_err, g_stage);
    put(g_err, " on ");
    put(g_err, g_origin);
    if (g_save) {
        put(g_err, "; input saved as ");
        put(g_err, path);
    }
    put(g_err, "\n");
}

void onFatalSignal(int sig, siginfo_t* info, void*) {
    const char* what = sig == SIGSEGV  ? "CRASH (SIGSEGV)"
                       : sig == SIGBUS ? "CRASH (SIGBUS)"
                       : sig == SIGILL ? "CRASH (SIGILL)"
                       : sig == SIGFPE ? "CRASH (SIGFPE)"
                                       : "CRASH (SIGABRT)";
    saveCurrent(g_crashPath, what);
    announce(what, g_crashPath);
    putSummary(g_out, 1, 0);
    for (std::size_t k = 0; k < sizeof(kFatalSignals) / sizeof(int); ++k)
        if (kFatalSignals[k] == sig) sigaction(sig, &g_previous[k], nullptr);  // sanitizer or default
    // A fault re-executes the faulting instruction on return, so the previous handler (ASan's
    // report, or the default core dump) sees the real context; a sent signal is sent again.
    if (info == nullptr || info->si_code <= 0) raise(sig);
}

void onAlarm(int sig) {
    const char* what = sig == SIGPROF ? "HANG (per-input CPU limit)" : "HANG (per-input wall limit)";
    saveCurrent(g_hangPath, what);
    announce(what, g_hangPath);
    putSummary(g_out, 0, 1);
    _exit(kExitHang);
}

#if defined(__SANITIZE_ADDRESS__)
void onSanitizerDeath() {
    saveCurrent(g_crashPath, "SANITIZER ERROR");
    announce("SANITIZER ERROR", g_crashPath);
    putSummary(g_out, 1, 0);
}
#endif

/// Starts (seconds > 0) or stops the per-input limits: `seconds` of CPU time (SIGPROF; a hang
/// spins at 100 % CPU, and CPU time does not depend on the machine's load) and, as a backstop
/// for an input that blocks, four times as much wall time (SIGALRM).
void setLimits(unsigned seconds) {
    itimerval cpu{};
    cpu.it_value.tv_sec = seconds;
    setitimer(ITIMER_PROF, &cpu, nullptr);
    alarm(4 * seconds);
}

}  // namespace

Counters& counters() {
    static Counters c;
    return c;
}

std::string summaryLine(std::uint64_t crashes, std::uint64_t hangs) {
    const Counters& c = counters();
    return fmt::format(
        "fuzz-summary mutants={} ok={} bad_input={} unstable={} exceptions={} crashes={} hangs={}\n",
        c.mutants, c.ok, c.badInput, c.unstable, c.exceptions, crashes, hangs);
}

void silenceEngines() {
    std::fflush(stdout);
    std::fflush(stderr);
    g_out = dup(STDOUT_FILENO);
    g_err = dup(STDERR_FILENO);
    const int null = open("/dev/null", O_WRONLY);
    if (g_out < 0 || g_err < 0 || null < 0) {
        g_out = STDOUT_FILENO;
        g_err = STDERR_FILENO;
        return;
    }
    dup2(null, STDOUT_FILENO);
#if defined(__SANITIZE_ADDRESS__)
    // Sanitized builds keep stderr: UBSan reports there whatever the report fd (the engines print
    // little on stderr with quiet options).
    __sanitizer_set_report_fd(reinterpret_cast<void*>(static_cast<std::intptr_t>(g_err)));
#else
    dup2(null, STDERR_FILENO);
#endif
    close(null);
}

void say(const std::string& text) {
    if (write(g_err, text.data(), text.size()) < 0) return;
}

void report(const std::string& text) {
    if (write(g_out, text.data(), text.size()) < 0) return;
}

void installHandlers(unsigned hangSeconds) {
    g_hangSeconds = hangSeconds;
    struct sigaction sa {};
    sa.sa_sigaction = onFatalSignal;
    sa.sa_flags = SA_SIGINFO;
    sigemptyset(&sa.sa_mask);
    for (std::size_t k = 0; k < sizeof(kFatalSignals) / sizeof(int); ++k)
        sigaction(kFatalSignals[k], &sa, &g_previous[k]);
    struct sigaction alarmAction {};
    alarmAction.sa_handler = onAlarm;
    sigemptyset(&alarmAction.sa_mask);
    sigaction(SIGALRM, &alarmAction, nullptr);
    sigaction(SIGPROF, &alarmAction, nullptr);
#if defined(__SANITIZE_ADDRESS__)
    __sanitizer_set_death_callback(onSanitizerDeath);
#endif
}

void beginInput(const std::string& text, const std::string& findingsDir, const std::string& origin) {
    g_save = !findingsDir.empty();
    if (g_save) {
        std::filesystem::create_directories(findingsDir);
        const std::string hash = fmt::format("{:016x}", fnv1a(text));
        copyString(g_crashPath, sizeof(g_crashPath), findingsDir + "/crash-" + hash + ".toml");
        copyString(g_hangPath, sizeof(g_hangPath), findingsDir + "/hang-" + hash + ".toml");
    }
    copyString(g_origin, sizeof(g_origin), origin);
    g_stage = "read";
    g_length = text.size();
    g_text = text.data();
    setLimits(g_hangSeconds);
}

void endInput() {
    setLimits(0);
    g_text = nullptr;
}

void setStage(const char* stage) {
    g_stage = stage;
}

std::string saveFinding(const std::string& kind, const std::string& text, const std::string& findingsDir,
                        const std::string& note) {
    if (findingsDir.empty()) return "";
    std::filesystem::create_directories(findingsDir);
    const std::string path = fmt::format("{}/{}-{:016x}.toml", findingsDir, kind, fnv1a(text));
    std::ofstream(path, std::ios::binary) << text;
    std::ofstream(path + ".txt") << note << "\n";
    return path;
}

}  // namespace granulab::fuzz
