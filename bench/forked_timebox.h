// Time-boxed, memory-capped runs of one benchmark repeat in a forked child process (fresh caches,
// fresh CORE DAG), shared by the benchmarks in bench/.
//
// run_forked(work, limit, memory) forks; the child sets an address-space limit, calls work() and
// writes its one-line result to a pipe; the parent kills the child with SIGKILL once `limit`
// seconds have passed. Outcome:
//   ok      : work() returned; `output` is its line,
//   wrong   : work() threw WrongAnswer (the benchmark computed a wrong verdict; callers must fail),
//   timeout : killed after the limit,
//   error   : any other exception, or the child died (e.g. out of memory under the cap);
//             `seconds` then says how long it ran.
#pragma once

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <stdexcept>
#include <string>

#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

namespace symmesh_bench {

/// Thrown by a benchmark body whose exact answer is not the expected one.
struct WrongAnswer : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct ForkedResult {
  enum class Status { ok, wrong, timeout, error } status = Status::error;
  std::string output; ///< the line returned by work() (status ok)
  double seconds = 0; ///< wall time until the child ended (or was killed), seen by the parent
};

inline const char* to_string(ForkedResult::Status s) {
  switch (s) {
  case ForkedResult::Status::ok:
    return "ok";
  case ForkedResult::Status::wrong:
    return "wrong";
  case ForkedResult::Status::timeout:
    return "timeout";
  case ForkedResult::Status::error:
    break;
  }
  return "error";
}

namespace detail {
constexpr int wrong_answer_exit = 3;

[[noreturn]] inline void child(const std::function<std::string()>& work, long memory_limit_mb,
                               const char* name, int fd) {
  if (memory_limit_mb > 0) {
    const rlim_t bytes = static_cast<rlim_t>(memory_limit_mb) * 1024 * 1024;
    const rlimit limit{bytes, bytes};
    setrlimit(RLIMIT_AS, &limit);
  }
  int code = 0;
  std::string line;
  try {
    line = work();
  } catch (const WrongAnswer& e) {
    std::fprintf(stderr, "%s: WRONG ANSWER: %s\n", name, e.what());
    code = wrong_answer_exit;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: %s\n", name, e.what());
    code = 1;
  }
  line += '\n';
  const ssize_t ignored = write(fd, line.data(), line.size());
  (void)ignored;
  close(fd);
  _exit(code);
}
} // namespace detail

inline ForkedResult run_forked(const std::function<std::string()>& work, double limit_seconds,
                               long memory_limit_mb, const char* name) {
  int fds[2];
  if (pipe(fds) != 0) throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
  std::fflush(stdout);
  std::fflush(stderr);
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error(std::string("fork: ") + std::strerror(errno));
  if (pid == 0) {
    close(fds[0]);
    detail::child(work, memory_limit_mb, name, fds[1]);
  }
  close(fds[1]);
  const auto started = std::chrono::steady_clock::now();
  const auto deadline = started + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                      std::chrono::duration<double>(limit_seconds));
  std::string output;
  bool timed_out = false;
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
                          deadline - std::chrono::steady_clock::now())
                          .count();
    if (left <= 0) {
      timed_out = true;
      break;
    }
    pollfd p{fds[0], POLLIN, 0};
    const int r = poll(&p, 1, static_cast<int>(left));
    if (r < 0 && errno == EINTR) continue;
    if (r == 0) {
      timed_out = true;
      break;
    }
    char buffer[256];
    const ssize_t got = read(fds[0], buffer, sizeof buffer);
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) break; // EOF: child finished (or died)
    output.append(buffer, static_cast<std::size_t>(got));
  }
  close(fds[0]);
  if (timed_out) kill(pid, SIGKILL);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }

  ForkedResult result;
  result.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  if (timed_out) {
    result.status = ForkedResult::Status::timeout;
    return result;
  }
  while (!output.empty() && output.back() == '\n') output.pop_back();
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0 && !output.empty()) {
    result.status = ForkedResult::Status::ok;
    result.output = output;
  } else if (WIFEXITED(status) && WEXITSTATUS(status) == detail::wrong_answer_exit) {
    result.status = ForkedResult::Status::wrong;
  }
  return result;
}

} // namespace symmesh_bench
