// Progress lines with a heartbeat (spec/outputs.md#progress).
#include "symmesh/mesh/progress.h"

#include <cstdio>
#include <string>
#include <stdexcept>

namespace symmesh::mesh {
namespace {
/// "STAGE: DONE/TOTAL UNIT", or "STAGE: running" for a stage without counts.
std::string counts(const std::string& stage, std::size_t done, std::size_t total,
                   const std::string& unit) {
  if (unit.empty()) return stage + ": running";
  return stage + ": " + std::to_string(done) + (total ? "/" + std::to_string(total) : "") + " " +
         unit;
}
} // namespace

Progress::Progress(std::string command, std::ostream& os, double interval_seconds)
    : command_(std::move(command)), os_(os),
      interval_(std::chrono::duration_cast<std::chrono::steady_clock::duration>(
          std::chrono::duration<double>(interval_seconds))),
      start_(std::chrono::steady_clock::now()), last_print_(start_) {
  if (!(interval_seconds > 0)) throw std::invalid_argument("Progress: interval must be positive");
  thread_ = std::thread([this] { heartbeat(); });
}

Progress::~Progress() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

double Progress::elapsed() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void Progress::print_locked(const std::string& text) {
  char seconds[32];
  std::snprintf(seconds, sizeof seconds, " [%.2f s]", elapsed());
  os_ << command_ << ": " << text << seconds << '\n' << std::flush;
  last_print_ = std::chrono::steady_clock::now();
}

void Progress::stage(const std::string& name, std::size_t total, const std::string& unit) {
  std::lock_guard<std::mutex> lock(mutex_);
  stage_ = name;
  unit_ = unit;
  done_.store(0, std::memory_order_relaxed);
  total_.store(total, std::memory_order_relaxed);
  in_stage_ = true;
  wake_.notify_all();
  // Silent until the heartbeat finds no line for `interval`: short stages print nothing.
}

void Progress::message(const std::string& line) {
  std::lock_guard<std::mutex> lock(mutex_);
  in_stage_ = false;
  print_locked(line);
}

void Progress::heartbeat() {
  std::unique_lock<std::mutex> lock(mutex_);
  while (!stopping_) {
    // Sleep until the line would be due; stage(), message() and the destructor wake it early.
    if (in_stage_)
      wake_.wait_until(lock, last_print_ + interval_);
    else
      wake_.wait_for(lock, interval_);
    if (stopping_ || !in_stage_) continue;
    if (std::chrono::steady_clock::now() - last_print_ < interval_) continue;
    const std::size_t done = done_.load(std::memory_order_relaxed);
    const std::size_t total = total_.load(std::memory_order_relaxed);
    print_locked(counts(stage_, done, total, unit_));
  }
}

} // namespace symmesh::mesh
