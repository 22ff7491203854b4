// Timed runs in child processes (child_run.hpp).
#include "child_run.hpp"

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <time.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <exception>
#include <numeric>

namespace peers {

namespace {

/// What the child sends before its step times.
struct Header {
  int ok = 0;
  char error[512] = {};
  Accuracy accuracy;
  Work work;
  double setupSeconds = 0.0;
  long steps = 0;
};

bool writeAll(int fd, const void* data, std::size_t bytes) {
  const char* p = static_cast<const char*>(data);
  while (bytes > 0) {
    const ssize_t n = ::write(fd, p, bytes);
    if (n <= 0) return false;
    p += n;
    bytes -= static_cast<std::size_t>(n);
  }
  return true;
}

bool readAll(int fd, void* data, std::size_t bytes) {
  char* p = static_cast<char*>(data);
  while (bytes > 0) {
    const ssize_t n = ::read(fd, p, bytes);
    if (n <= 0) return false;
    p += n;
    bytes -= static_cast<std::size_t>(n);
  }
  return true;
}

[[noreturn]] void child(int fd, const std::function<std::unique_ptr<Engine>()>& make, long steps) {
  Header h;
  std::vector<double> times;
  std::vector<double> cpu;
  const auto cpuNow = [] {
    timespec t{};
    ::clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
  };
  try {
    using clock = std::chrono::steady_clock;
    const auto t0 = clock::now();
    std::unique_ptr<Engine> engine = make();
    if (!engine) throw std::runtime_error("no such engine for this scene");
    engine->startTiming();
    h.setupSeconds = std::chrono::duration<double>(clock::now() - t0).count();
    times.reserve(static_cast<std::size_t>(steps));
    cpu.reserve(static_cast<std::size_t>(steps));
    for (long n = 0; n < steps; ++n) {
      const double c = cpuNow();
      const auto a = clock::now();
      engine->step();
      times.push_back(std::chrono::duration<double>(clock::now() - a).count());
      cpu.push_back(cpuNow() - c);
    }
    h.accuracy = engine->accuracy();
    h.work = engine->work();
    h.ok = 1;
  } catch (const std::exception& e) {
    std::snprintf(h.error, sizeof h.error, "%s", e.what());
  }
  h.steps = static_cast<long>(times.size());
  const bool sent = writeAll(fd, &h, sizeof h) && writeAll(fd, times.data(), times.size() * sizeof(double)) &&
                    writeAll(fd, cpu.data(), cpu.size() * sizeof(double));
  ::close(fd);
  ::_exit(sent ? 0 : 1);
}

}  // namespace

RunResult runInChild(const std::function<std::unique_ptr<Engine>()>& make, long steps) {
  RunResult r;
  int fds[2];
  if (::pipe(fds) != 0) {
    r.error = "pipe() failed";
    return r;
  }
  std::fflush(nullptr);
  const pid_t pid = ::fork();
  if (pid < 0) {
    r.error = "fork() failed";
    return r;
  }
  if (pid == 0) {
    ::close(fds[0]);
    child(fds[1], make, steps);
  }
  ::close(fds[1]);
  Header h;
  const bool gotHeader = readAll(fds[0], &h, sizeof h);
  if (gotHeader && h.steps > 0) {
    r.stepSeconds.resize(static_cast<std::size_t>(h.steps));
    r.stepCpuSeconds.resize(static_cast<std::size_t>(h.steps));
    if (!readAll(fds[0], r.stepSeconds.data(), r.stepSeconds.size() * sizeof(double)) ||
        !readAll(fds[0], r.stepCpuSeconds.data(), r.stepCpuSeconds.size() * sizeof(double))) {
      r.stepSeconds.clear();
      r.stepCpuSeconds.clear();
    }
  }
  ::close(fds[0]);
  int status = 0;
  struct rusage usage {};
  ::wait4(pid, &status, 0, &usage);
  r.peakKilobytes = usage.ru_maxrss;
  if (!gotHeader) {
    r.error = WIFSIGNALED(status) ? std::string("the run died of signal ") + std::to_string(WTERMSIG(status))
                                  : std::string("the run sent no result");
    return r;
  }
  r.ok = h.ok != 0;
  r.error = h.error;
  r.accuracy = h.accuracy;
  r.work = h.work;
  r.setupSeconds = h.setupSeconds;
  return r;
}

double minimum(const std::vector<double>& v) { return v.empty() ? 0.0 : *std::min_element(v.begin(), v.end()); }

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

double mean(const std::vector<double>& v) {
  return v.empty() ? 0.0 : std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
}

}  // namespace peers
