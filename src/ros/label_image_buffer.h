#pragma once

#include <ros/time.h>
#include <sensor_msgs/Image.h>

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <mutex>

namespace vdc {

// The newest label images of a detector, for the clouds they belong to: the subscriber's
// callback adds each, the worker thread that processes a cloud takes the one of the cloud's
// stamp, waiting for it a little, since a detector is often slower than the camera.
class LabelImageBuffer {
 public:
  explicit LabelImageBuffer(std::size_t capacity) : capacity_(capacity) {}

  // Keeps the image (dropping the oldest beyond capacity) and wakes a waiting find.
  void add(const sensor_msgs::ImageConstPtr& image);

  // The image whose stamp is nearest `stamp` within `tolerance` [s], waiting up to `timeout` [s]
  // for one to arrive; null if none did.
  sensor_msgs::ImageConstPtr find(const ros::Time& stamp, double tolerance, double timeout);

  std::size_t size();

 private:
  sensor_msgs::ImageConstPtr nearest(const ros::Time& stamp, double tolerance) const;

  const std::size_t capacity_;
  std::mutex mutex_;
  std::condition_variable added_;
  std::deque<sensor_msgs::ImageConstPtr> images_;  // oldest first
};

}  // namespace vdc
