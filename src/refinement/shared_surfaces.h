#pragma once

// Model surfaces shared between refiners (private to refinement). The scene layer gives every
// candidate a fresh estimator of each model that fits it, each with its own refiner: building
// each one's surface (a k-d tree, the symmetry axes, the screening's distance field) anew cost
// more than a quarter of a scene's first view (doc/performance.md). A surface is immutable, so
// every refiner of one bundle at one spacing may share it.

#include <memory>

#include "view_direction_classification/refinement/model_surface.h"
#include "view_direction_classification/training/model_bundle.h"

namespace vdc {

// The surface of `model`'s samples thinned to `spacing` [m] (ModelSurface), the one already
// built for the same bundle and spacing while any refiner still holds it, else a new one.
// The bundle is recognised by its address and its samples (their count, the first and last,
// their spacing and the bounds), so a new bundle at a freed one's address is not mistaken for
// it. Thread-safe. Throws as ModelSurface does.
std::shared_ptr<const ModelSurface> sharedModelSurface(const ModelBundle& model, double spacing);

}  // namespace vdc
