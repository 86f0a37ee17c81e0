#pragma once

#include <view_direction_classification/BinghamComponent.h>
#include <view_direction_classification/BinghamMixture.h>

#include "view_direction_classification/bingham/bingham.h"
#include "view_direction_classification/bingham/bingham_mixture.h"

namespace vdc {

// The message types share their names with the core's types; these aliases keep them apart.
using BinghamComponentMsg = view_direction_classification::BinghamComponent;
using BinghamMixtureMsg = view_direction_classification::BinghamMixture;

// A component as a message: weight, concentrations, axes and mode copied unchanged (so the
// axes and concentrations survive a round trip bit for bit), normaliser F.
BinghamComponentMsg toBinghamComponentMsg(double weight, const BinghamDistribution& component);

// The mixture's components as a message. Header, object_id, map_orientation and entropy are
// left for the caller: they are the publisher's knowledge (frame, object) or costly to compute.
BinghamMixtureMsg toBinghamMixtureMsg(const BinghamMixture& mixture);

// The distribution of a component message. Throws vdc::Error naming the component (`index`) and
// the problem for non-finite or positive concentrations, axes that are not unit and orthonormal,
// a mode that is not orthogonal to the axes, or a normaliser that disagrees with the
// concentrations (relative 1e-6): such a message was corrupted or built by hand.
BinghamDistribution fromBinghamComponentMsg(const BinghamComponentMsg& msg, std::size_t index);

// The mixture of a message (weights renormalised). Throws vdc::Error for no components,
// non-finite or negative weights, weights summing to zero, or any invalid component.
BinghamMixture fromBinghamMixtureMsg(const BinghamMixtureMsg& msg);

}  // namespace vdc
