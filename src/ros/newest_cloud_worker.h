#pragma once

#include <sensor_msgs/PointCloud2.h>

#include <condition_variable>
#include <functional>
#include <mutex>
#include <string>
#include <thread>

namespace vdc {

// The hand-over between a cloud subscription and one worker thread that processes only the
// newest cloud: a camera can be faster than the estimator, and a cloud that waited while a newer
// one arrived is worth nothing. The subscription's callback offers each cloud (replacing an
// unprocessed one, which is dropped); the worker processes whatever is newest when it is free.
// Whatever `process` throws costs that cloud, not the node: it goes to `failed` as a reason.
class NewestCloudWorker {
 public:
  using Process = std::function<void(const sensor_msgs::PointCloud2&)>;
  using Failed = std::function<void(const std::string& reason)>;

  // Starts the worker thread.
  NewestCloudWorker(Process process, Failed failed);
  // Stops the worker after the cloud it is processing, if any.
  ~NewestCloudWorker();
  NewestCloudWorker(const NewestCloudWorker&) = delete;
  NewestCloudWorker& operator=(const NewestCloudWorker&) = delete;

  // From the subscription's callback. True when it replaced a cloud the worker had not taken.
  bool offer(const sensor_msgs::PointCloud2ConstPtr& cloud);

 private:
  void loop();

  Process process_;
  Failed failed_;
  std::mutex mutex_;
  std::condition_variable changed_;
  sensor_msgs::PointCloud2ConstPtr pending_;
  bool stopping_ = false;
  std::thread thread_;  // last: started once everything above exists
};

}  // namespace vdc
