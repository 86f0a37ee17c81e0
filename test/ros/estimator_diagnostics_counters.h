#pragma once

// The orientation_estimator's diagnostics counters (clouds received, skipped, fused...) as a
// rostest sees them on /diagnostics, so a test can wait until the node has handled a message
// instead of sleeping for a guessed time.

#include <diagnostic_msgs/DiagnosticArray.h>
#include <ros/ros.h>

#include <condition_variable>
#include <cstdint>
#include <map>
#include <mutex>
#include <optional>
#include <string>

namespace vdc {

class EstimatorDiagnosticsCounters {
 public:
  // The counters' keys, as OrientationEstimatorRos::diagnose names them.
  static constexpr const char* kReceived = "clouds received";
  static constexpr const char* kFused = "clouds fused (new views)";
  static constexpr const char* kSkipped = "clouds skipped (bad input or no tf)";

  // status: the status whose values are read ("scene estimate" for the scene layer).
  explicit EstimatorDiagnosticsCounters(ros::NodeHandle& node,
                                        const std::string& status = "orientation estimate")
      : status_(status),
        subscriber_(node.subscribe("/diagnostics", 10,
                                   &EstimatorDiagnosticsCounters::diagnosticsCallback, this)) {}

  // The counter's latest value, waiting up to `timeout` [s] for the first report. Empty when
  // the node has not reported it.
  std::optional<std::uint64_t> current(const std::string& key, double timeout) {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait_for(lock, std::chrono::duration<double>(timeout),
                      [&] { return counters_.count(key) > 0; });
    const auto found = counters_.find(key);
    if (found == counters_.end()) return std::nullopt;
    return found->second;
  }

  // The latest value of a key that is no counter (a reason), "" before the first report.
  std::string text(const std::string& key) {
    std::lock_guard<std::mutex> lock(mutex_);
    const auto found = texts_.find(key);
    return found == texts_.end() ? "" : found->second;
  }

  // Waits up to `timeout` [s] until the counter exceeds `before`; false if it did not.
  bool waitUntilAbove(const std::string& key, std::uint64_t before, double timeout) {
    std::unique_lock<std::mutex> lock(mutex_);
    return changed_.wait_for(lock, std::chrono::duration<double>(timeout), [&] {
      const auto found = counters_.find(key);
      return found != counters_.end() && found->second > before;
    });
  }

 private:
  void diagnosticsCallback(const diagnostic_msgs::DiagnosticArray& array) {
    std::lock_guard<std::mutex> lock(mutex_);
    for (const diagnostic_msgs::DiagnosticStatus& status : array.status) {
      // diagnostic_updater names it "<node>: orientation estimate".
      if (status.name.find(status_) == std::string::npos) continue;
      for (const diagnostic_msgs::KeyValue& entry : status.values) {
        texts_[entry.key] = entry.value;
        try {
          counters_[entry.key] = std::stoull(entry.value);
        } catch (const std::exception&) {
          // Not a counter (a reason or a time): only its text is kept.
        }
      }
    }
    changed_.notify_all();
  }

  std::mutex mutex_;
  std::condition_variable changed_;
  const std::string status_;
  std::map<std::string, std::uint64_t> counters_;
  std::map<std::string, std::string> texts_;
  ros::Subscriber subscriber_;
};

}  // namespace vdc
