#include "scene/child_process.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <exception>
#include <fstream>
#include <new>

namespace shadowlab {
namespace {

// The child's first byte says how its work ended; the rest is the answer or the exception's text.
constexpr char kAnswered = 'A', kThrew = 'T', kOutOfMemory = 'M';

// How often the caller looks at the child's memory while it waits.
constexpr int kWatchMilliseconds = 20;

std::string gibibytes(std::size_t bytes) {
    const double gib = static_cast<double>(bytes) / double(std::size_t{1} << 30);
    return std::to_string(static_cast<long long>(std::llround(gib))) + " GiB";
}

// The resident memory of a process (/proc/PID/statm's second field, in pages).
std::size_t resident_bytes(pid_t pid) {
    std::ifstream statm("/proc/" + std::to_string(pid) + "/statm");
    std::size_t size = 0, resident = 0;
    statm >> size >> resident;
    return resident * static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
}

void write_all(int fd, const std::string& bytes) {
    std::size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return;
        done += static_cast<std::size_t>(n);
    }
}

// In the child: the work, its outcome through the pipe, then _exit (no atexit handlers, no
// destructors of the parent's objects: the child owns nothing of them).
[[noreturn]] void be_the_child(int fd, const std::function<std::string()>& work) {
    // A crash here is the child's own: the caller's handlers (a sanitizer's, a fuzzer's) would
    // report it as the caller's and exit with their own status instead of dying by the signal.
    for (int fatal : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) std::signal(fatal, SIG_DFL);
    std::string message;
    try {
        message = std::string(1, kAnswered) + work();
    } catch (const std::bad_alloc&) {
        message = std::string(1, kOutOfMemory);
    } catch (const std::exception& error) {
        message = std::string(1, kThrew) + error.what();
    } catch (...) {
        message = std::string(1, kThrew) + "an exception that is not a std::exception";
    }
    write_all(fd, message);
    close(fd);
    _exit(0);
}

enum class Wait { closed, out_of_time, out_of_memory };

// Reads the child's bytes until it closes the pipe (done, or dead), watching its time and memory.
Wait read_until_closed(int fd, pid_t child, const ChildLimits& limits, std::string& bytes) {
    using Clock = std::chrono::steady_clock;
    const Clock::time_point deadline =
        Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(limits.seconds));
    const std::size_t memory_limit = resident_bytes(getpid()) + limits.extra_bytes;
    char buffer[1 << 16];
    for (;;) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
        if (left <= 0) return Wait::out_of_time;
        if (resident_bytes(child) > memory_limit) return Wait::out_of_memory;
        pollfd readable{.fd = fd, .events = POLLIN, .revents = 0};
        const int ready = poll(&readable, 1, static_cast<int>(std::min<long long>(left, kWatchMilliseconds)));
        if (ready <= 0) continue;  // nothing yet, or interrupted
        const ssize_t n = read(fd, buffer, sizeof buffer);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return Wait::closed;
        bytes.append(buffer, static_cast<std::size_t>(n));
    }
}

std::string signal_text(int signal) {
    const char* name = sigabbrev_np(signal);
    return "crashed (signal " + std::to_string(signal) + (name ? std::string(", SIG") + name : "") + ")";
}

std::string seconds_text(double seconds) {
    std::string text = std::to_string(seconds);
    text.erase(text.find_last_not_of('0') + 1);
    if (text.back() == '.') text.pop_back();
    return text + " s";
}

// What the child's exit status and first byte say.
ChildResult outcome(int status, std::string bytes) {
    if (WIFSIGNALED(status)) return {.bytes = {}, .failure = signal_text(WTERMSIG(status))};
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
        return {.bytes = {}, .failure = "exited with status " + std::to_string(WEXITSTATUS(status))};
    if (bytes.empty()) return {.bytes = {}, .failure = "ended without an answer"};
    const char first = bytes.front();
    bytes.erase(0, 1);
    switch (first) {
        case kAnswered: return {.bytes = std::move(bytes), .failure = {}};
        case kOutOfMemory: return {.bytes = {}, .failure = "ran out of memory"};
        case kThrew: return {.bytes = {}, .failure = "threw: " + bytes};
    }
    return {.bytes = {}, .failure = "answered in an unknown form"};
}

}  // namespace

ChildResult run_in_child(const std::function<std::string()>& work, const ChildLimits& limits) {
    int pipe_ends[2];
    if (pipe2(pipe_ends, O_CLOEXEC) != 0)
        return {.bytes = {}, .failure = "no pipe: " + std::string(std::strerror(errno))};
    const pid_t child = fork();
    if (child < 0) {
        close(pipe_ends[0]);
        close(pipe_ends[1]);
        return {.bytes = {}, .failure = "no child process: " + std::string(std::strerror(errno))};
    }
    if (child == 0) {
        close(pipe_ends[0]);
        be_the_child(pipe_ends[1], work);
    }
    close(pipe_ends[1]);
    std::string bytes;
    const Wait wait = read_until_closed(pipe_ends[0], child, limits, bytes);
    close(pipe_ends[0]);
    if (wait != Wait::closed) kill(child, SIGKILL);
    int status = 0;
    while (waitpid(child, &status, 0) < 0 && errno == EINTR) {
    }
    if (wait == Wait::out_of_time) return {.bytes = {}, .failure = "took over " + seconds_text(limits.seconds)};
    if (wait == Wait::out_of_memory)
        return {.bytes = {}, .failure = "took over " + gibibytes(limits.extra_bytes) + " of memory"};
    return outcome(status, std::move(bytes));
}

}  // namespace shadowlab
