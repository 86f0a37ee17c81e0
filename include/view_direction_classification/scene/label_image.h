#pragma once

#include <cstdint>
#include <vector>

namespace vdc {

// A detector's instance label image, pixel-aligned with an organised cloud: labels[row * width +
// column] belongs to the cloud's point at (column, row). 0 is background; every other value is
// one instance, of the class value / label_class_divisor (the Cityscapes instance images'
// convention: 26001 is instance 1 of class 26 with the divisor 1000). Apart from the segmentation
// (label_segmentation.h), so that the message conversion needs no PCL.
struct LabelImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint32_t> labels;
};

}  // namespace vdc
