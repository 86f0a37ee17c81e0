#include "newest_cloud_worker.h"

#include <exception>
#include <utility>

namespace vdc {

NewestCloudWorker::NewestCloudWorker(Process process, Failed failed)
    : process_(std::move(process)),
      failed_(std::move(failed)),
      thread_(&NewestCloudWorker::loop, this) {}

NewestCloudWorker::~NewestCloudWorker() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  changed_.notify_all();
  if (thread_.joinable()) thread_.join();
}

bool NewestCloudWorker::offer(const sensor_msgs::PointCloud2ConstPtr& cloud) {
  bool replaced = false;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    replaced = static_cast<bool>(pending_);
    pending_ = cloud;
  }
  changed_.notify_one();
  return replaced;
}

void NewestCloudWorker::loop() {
  while (true) {
    sensor_msgs::PointCloud2ConstPtr cloud;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      changed_.wait(lock, [this] { return stopping_ || pending_; });
      if (stopping_) return;
      cloud.swap(pending_);
    }
    try {
      process_(*cloud);
    } catch (const std::exception& error) {
      // Anything the core did not foresee (e.g. memory for a gigantic cloud) costs one cloud,
      // not the node.
      failed_(std::string("processing the cloud failed: ") + error.what());
    }
  }
}

}  // namespace vdc
