#pragma once
// The rolling contact of the paper's point models (§4): contact points moving along a road at
// constant speed, one exact LCP per time step (MODEL.md §2).
#include <string>
#include <vector>

#include <Eigen/Core>

#include "contact/rolling_settings.hpp"

namespace rollnoise {

class GreensModel;
class RoadProfile;
class ProgressReporter;

struct ContactTrace {
  Eigen::VectorXd time;          // s, one entry per sample t = nΔt, n = 0 … steps
  Eigen::MatrixXd road;          // r under each point (samples × points), m
  Eigen::MatrixXd displacement;  // vertical position of each contact point, same datum as road, m
  Eigen::MatrixXd force;         // contact force, N (≥ 0)
  Eigen::MatrixXd gap;           // displacement − road, m (≥ 0; 0 in contact)
  std::vector<int> lcp_iterations;  // active-set changes per step
  double indentation = 0.0;         // d from the static load, m
  Eigen::VectorXd preload_force;    // static force per point, N
  std::string engine;               // history engine used
  std::vector<std::string> warnings;
};

// Warnings about the settings for this model (a time step too coarse for its dynamics).
std::vector<std::string> check_time_step(const GreensModel& model, double time_step);

ContactTrace simulate_point_contact(const GreensModel& model, const RoadProfile& road,
                                    const RollingSettings& settings,
                                    ProgressReporter* progress = nullptr);

}  // namespace rollnoise
