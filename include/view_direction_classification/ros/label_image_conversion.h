#pragma once

#include <sensor_msgs/Image.h>

#include "view_direction_classification/scene/label_image.h"

namespace vdc {

// A detector's instance label image (sensor_msgs/Image) as the core's LabelImage: encodings
// mono8 / 8UC1, mono16 / 16UC1 (either byte order) and 32SC1 (either byte order; a negative value
// is background, as 0 is). Checked first, because an inconsistent message would be read past its
// buffer: throws vdc::Error naming the problem for another encoding, a step shorter than a row
// (width x bytes per pixel), data shorter than height x step, or a width or height beyond what
// a LabelImage holds. Whether it matches a cloud's size is the caller's to check.
LabelImage toLabelImage(const sensor_msgs::Image& msg);

}  // namespace vdc
