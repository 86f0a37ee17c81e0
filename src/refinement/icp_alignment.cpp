#include "icp_alignment.h"

#include <pcl/registration/icp.h>
#include <pcl/registration/transformation_estimation_point_to_plane_lls.h>
#include <pcl/search/kdtree.h>

#include <cmath>

namespace vdc {

namespace {

// PCL's linearised point-to-plane step solves a 6 x 6 system by inversion: where the matched
// surface leaves a motion unconstrained (a cylinder's roll and slide, a plane's drift) it is
// singular, the step is NaN and the next correspondence search aborts. Such a step becomes no
// step, and the alignment is refused as degenerate.
class FiniteStepPointToPlane
    : public pcl::registration::TransformationEstimationPointToPlaneLLS<pcl::PointNormal,
                                                                        pcl::PointNormal> {
 public:
  using Base = pcl::registration::TransformationEstimationPointToPlaneLLS<pcl::PointNormal,
                                                                          pcl::PointNormal>;
  using Base::estimateRigidTransformation;

  void estimateRigidTransformation(const pcl::PointCloud<pcl::PointNormal>& source,
                                   const pcl::PointCloud<pcl::PointNormal>& target,
                                   const pcl::Correspondences& correspondences,
                                   Matrix4& transform) const override {
    Base::estimateRigidTransformation(source, target, correspondences, transform);
    if (!transform.allFinite()) {
      transform.setIdentity();
      degenerate = true;
    }
  }

  mutable bool degenerate = false;
};

}  // namespace

struct IcpAlignment::Registration {
  pcl::IterativeClosestPointWithNormals<pcl::PointNormal, pcl::PointNormal> icp;
  std::shared_ptr<FiniteStepPointToPlane> step = std::make_shared<FiniteStepPointToPlane>();
};

IcpAlignment::IcpAlignment(std::shared_ptr<const ModelSurface> surface,
                           pcl::PointCloud<pcl::PointNormal>::Ptr observed_world,
                           IcpSettings settings)
    : registration_(std::make_unique<Registration>()) {
  auto& icp = registration_->icp;
  // The observed points are the source and the model the target: point-to-plane uses the
  // target's normals, which the model has exactly (the mesh's), so the scene needs none.
  icp.setInputSource(observed_world);
  icp.setInputTarget(surface->cloud());
  // One k-d tree of the model for every start (PCL would rebuild it on each align()).
  pcl::search::KdTree<pcl::PointNormal>::Ptr tree(new pcl::search::KdTree<pcl::PointNormal>);
  tree->setInputCloud(surface->cloud());
  icp.setSearchMethodTarget(tree, true);
  icp.setTransformationEstimation(registration_->step);
  icp.setMaximumIterations(settings.max_iterations);
  icp.setMaxCorrespondenceDistance(settings.max_correspondence_distance);
  // Converged when a step moves the pose by less than 0.1 mm and 0.05 degrees, or the mean
  // squared distance changes by less than 0.01 % (PCL's "Euclidean fitness epsilon" is relative).
  icp.setTransformationEpsilon(1e-8);
  icp.setTransformationRotationEpsilon(std::cos(0.05 * M_PI / 180.0));
  icp.setEuclideanFitnessEpsilon(1e-4);
  // Running out of iterations is not convergence.
  icp.getConvergeCriteria()->setFailureAfterMaximumIterations(true);
}

IcpAlignment::~IcpAlignment() = default;

IcpOutcome IcpAlignment::align(const Eigen::Isometry3d& start_object_from_world) {
  auto& icp = registration_->icp;
  pcl::PointCloud<pcl::PointNormal> aligned;
  registration_->step->degenerate = false;
  icp.align(aligned, start_object_from_world.matrix().cast<float>());
  IcpOutcome outcome;
  const Eigen::Matrix4d transform = icp.getFinalTransformation().cast<double>();
  outcome.degenerate = registration_->step->degenerate;
  outcome.converged = icp.hasConverged() && !outcome.degenerate && transform.allFinite();
  if (!outcome.converged) return outcome;
  // Re-orthonormalise: ICP composes its steps in single precision.
  const Eigen::Quaterniond rotation(Eigen::Matrix3d(transform.topLeftCorner<3, 3>()));
  outcome.object_from_world.linear() = rotation.normalized().toRotationMatrix();
  outcome.object_from_world.translation() = transform.topRightCorner<3, 1>();
  outcome.fitness =
      icp.getFitnessScore(icp.getMaxCorrespondenceDistance() * icp.getMaxCorrespondenceDistance());
  return outcome;
}

}  // namespace vdc
