#pragma once
// A small deterministic chain that proves the runtime (not a substitute for any real component):
//   chain_plant:      x' = v, v' = u(k-1) - c v + w,  w ~ N(0, sigma_w^2) per step (its own stream)
//   chain_sensor:     y = x + n,  n ~ N(0, sigma_n^2)
//   chain_filter:     alpha-beta filter on y
//   chain_controller: u = -kp (x_hat - target) - kd v_hat   (fed back to the plant one step later)
#include "chain.h"
#include "framework/component.hpp"
#include "framework/registry.hpp"

namespace gdnav::testchain {

inline constexpr const char* kState = "chain/state";
inline constexpr const char* kMeas = "chain/meas";
inline constexpr const char* kEstimate = "chain/estimate";
inline constexpr const char* kControl = "chain/control";

void register_chain(framework::ComponentRegistry& reg);  // components and topics

}  // namespace gdnav::testchain
