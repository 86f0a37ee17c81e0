#include "label_image_buffer.h"

#include <chrono>
#include <cmath>

namespace vdc {

void LabelImageBuffer::add(const sensor_msgs::ImageConstPtr& image) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    images_.push_back(image);
    while (images_.size() > capacity_) images_.pop_front();
  }
  added_.notify_all();
}

sensor_msgs::ImageConstPtr LabelImageBuffer::find(const ros::Time& stamp, double tolerance,
                                                  double timeout) {
  std::unique_lock<std::mutex> lock(mutex_);
  sensor_msgs::ImageConstPtr found;
  added_.wait_for(lock, std::chrono::duration<double>(timeout), [&] {
    found = nearest(stamp, tolerance);
    return found != nullptr;
  });
  return found;
}

std::size_t LabelImageBuffer::size() {
  std::lock_guard<std::mutex> lock(mutex_);
  return images_.size();
}

sensor_msgs::ImageConstPtr LabelImageBuffer::nearest(const ros::Time& stamp,
                                                     double tolerance) const {
  sensor_msgs::ImageConstPtr best;
  double best_offset = tolerance;
  for (const sensor_msgs::ImageConstPtr& image : images_) {
    const double offset = std::abs((image->header.stamp - stamp).toSec());
    if (offset <= best_offset) {
      best = image;
      best_offset = offset;
    }
  }
  return best;
}

}  // namespace vdc
