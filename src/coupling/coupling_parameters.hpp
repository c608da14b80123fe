#pragma once
// Coefficients of seed 003's crown–root balance (scenario table [coupling], docs/formats.md):
//   LP_n = ρ Σ L_i,  WP_n = τ Σ W_j,  Branch_n = α_b (min(WP_n/LP_n, 2) − 1),  Root_n = α_r (min(LP_n/WP_n, 2) − 1)
// The seed gives no values; ours are in docs/model.md ("Seed 003: crown–root coupling").
namespace heliostand {

struct CouplingParameters {
  bool enabled = true;       // false: roots grow with Root_n = 0 and the crown with Branch_n = 0
  double rho = 1.0;          // ρ, per unit of leaf-ball light (relative light × sky scale)
  double tau = 1.0;          // τ, per unit of available uptake (m of fresh absorptive root × moisture × nutrient)
  double alpha_b = 0.5;      // α_b: Branch_n lies in [−α_b, α_b] (added to a lateral bud's flushing probability)
  double alpha_r = 0.5;      // α_r: Root_n lies in [−α_r, α_r] (added to a root apex's branching frequency)
};

}  // namespace heliostand
