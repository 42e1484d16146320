/// Progress lines of long work — spec/outputs.md#progress
///
/// Every stage that can take more than a second reports "COMMAND: STAGE: DONE/TOTAL UNIT
/// [ELAPSED s]" on stderr. The work only bumps an atomic counter; a heartbeat thread prints the
/// line at least every `interval` seconds while a stage runs, so a stage stuck inside one long
/// library call (Mesh_2, Gmsh) still shows that it is alive. The thread touches no mesh data,
/// only the counters and the stream, so the single-threaded CGAL build is unaffected.
#pragma once
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <mutex>
#include <ostream>
#include <string>
#include <thread>

namespace symmesh::mesh {

class Progress {
public:
  /// \pre interval_seconds > 0
  Progress(std::string command, std::ostream& os, double interval_seconds = 2.0);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  /// Starts a stage of `total` units (0 = unknown; unit "" = no counts). It prints nothing
  /// itself: the heartbeat prints it once no line was printed for `interval`.
  void stage(const std::string& name, std::size_t total, const std::string& unit);
  /// Sets the units done so far in the current stage (cheap: one relaxed atomic store).
  void set_done(std::size_t done) { done_.store(done, std::memory_order_relaxed); }
  void add_done(std::size_t n) { done_.fetch_add(n, std::memory_order_relaxed); }
  /// Ends the current stage (the heartbeat stops reporting it) and prints `line`.
  void message(const std::string& line);
  double elapsed() const;

private:
  void print_locked(const std::string& text);
  void heartbeat();

  std::string command_, stage_, unit_;
  std::ostream& os_;
  std::chrono::steady_clock::duration interval_;
  std::chrono::steady_clock::time_point start_, last_print_;
  std::atomic<std::size_t> done_{0}, total_{0};
  bool in_stage_ = false, stopping_ = false;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::thread thread_;
};

} // namespace symmesh::mesh
