// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The certified flows' energy, D_area as a barrier on the signed areas.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_AREA_BARRIER_ENERGY_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_AREA_BARRIER_ENERGY_H

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// The barrier energy in closed form. With u_t the signed domain areas,
/// U = Σ u_t, c_t = (A_t / Σ A)², the area-weighted mean of r_t = (u_t/U)/(A_t/ΣA)
/// is 1, hence E = Σ w_t (r_t + 1/r_t) = 1 + U Σ_t c_t / u_t and
/// ∂E/∂u_t = Σ_s c_s/u_s − U c_t / u_t².
class Area_barrier_energy
{
public:
  explicit Area_barrier_energy(const std::vector<double>& target) : m_c(target.size())
  {
    double T = 0;
    for(double a : target) T += a;
    for(std::size_t t = 0; t < target.size(); ++t) m_c[t] = (target[t] / T) * (target[t] / T);
  }

  /// E(u), +∞ when a face is not positive.
  double value(const std::vector<double>& u) const
  {
    double U = 0, K = 0;
    for(std::size_t t = 0; t < u.size(); ++t) {
      if(!(u[t] > 0)) return std::numeric_limits<double>::infinity();
      U += u[t];
      K += m_c[t] / u[t];
    }
    return 1 + U * K;
  }

  /// ∂E/∂u_t for every face (u all positive).
  void derivatives(const std::vector<double>& u, std::vector<double>& dE) const
  {
    double U = 0, K = 0;
    for(std::size_t t = 0; t < u.size(); ++t) { U += u[t]; K += m_c[t] / u[t]; }
    dE.resize(u.size());
    for(std::size_t t = 0; t < u.size(); ++t) dE[t] = K - U * m_c[t] / (u[t] * u[t]);
  }

  /// c_t = (A_t / Σ A)².
  double weight(std::size_t t) const { return m_c[t]; }
  std::size_t size() const { return m_c.size(); }

  /// The diagonal of the Hessian, ∂²E/∂u_t² ≈ 2 U c_t / u_t³ (the
  /// O(1/U²) terms of the global coupling through U dropped: they are a
  /// factor F smaller), for the Gauss–Newton model of the spherical flow.
  void curvatures(const std::vector<double>& u, std::vector<double>& w) const
  {
    double U = 0;
    for(double x : u) U += x;
    w.resize(u.size());
    for(std::size_t t = 0; t < u.size(); ++t) w[t] = 2 * U * m_c[t] / (u[t] * u[t] * u[t]);
  }

private:
  std::vector<double> m_c;
};

/// D_area with other face weights, for the spherical polish (sphere_certified_flow.h):
/// E = Σ ω_t (r_t + 1/r_t) with r_t = (u_t/U)/a_t as above, a_t = A_t/Σ A,
/// and ω_t ∝ (1 − β) a_t + β min(1/F, 100 a_t), Σ ω = 1. With α_t = ω_t/a_t
/// and c_t = ω_t a_t, E = P/U + U K, P = Σ α_t u_t, K = Σ c_t/u_t (β = 0:
/// P = U, the energy above). The minimum is still r ≡ 1; the weights decide
/// where the residual sits when it cannot vanish: area weights leave it on
/// the small faces, which the mean |log area ratio| counts like the others.
/// The cap keeps a face whose target is next to nothing (a 3D triangle
/// collinear up to rounding) from dominating: with the plain uniform share
/// its ω/a of ~1e15 made the flow crush its neighbours (D_area 11.5).
class Weighted_area_energy
{
public:
  /// The running sums of a configuration (updated face by face by the sweeps).
  struct Sums
  {
    double U = 0, K = 0, P = 0;
  };

  Weighted_area_energy(const std::vector<double>& target, double uniform_share)
    : m_a(target.size()), m_alpha(target.size()), m_c(target.size())
  {
    double T = 0;
    for(double x : target) T += x;
    const double F = double(target.size());
    std::vector<double> w(target.size());
    double W = 0;
    for(std::size_t t = 0; t < target.size(); ++t) {
      m_a[t] = target[t] / T;
      w[t] = (1 - uniform_share) * m_a[t] + uniform_share * (std::min)(1 / F, 100 * m_a[t]);
      W += w[t];
    }
    for(std::size_t t = 0; t < target.size(); ++t) {
      m_alpha[t] = (w[t] / W) / m_a[t];
      m_c[t] = (w[t] / W) * m_a[t];
    }
  }

  /// The sums of u (all positive).
  Sums sums(const std::vector<double>& u) const
  {
    Sums s;
    for(std::size_t t = 0; t < u.size(); ++t) {
      s.U += u[t];
      s.P += m_alpha[t] * u[t];
      s.K += m_c[t] / u[t];
    }
    return s;
  }
  /// Face t's element goes from `from` to `to` (both positive).
  void change(Sums& s, std::size_t t, double from, double to) const
  {
    s.U += to - from;
    s.P += m_alpha[t] * (to - from);
    s.K += m_c[t] * (1 / to - 1 / from);
  }
  double value(const Sums& s) const { return s.P / s.U + s.U * s.K; }
  /// E(u), +∞ when a face is not positive.
  double value(const std::vector<double>& u) const
  {
    for(double x : u)
      if(!(x > 0)) return std::numeric_limits<double>::infinity();
    return value(sums(u));
  }
  /// ∂E/∂u_t at u_t = x.
  double derivative(const Sums& s, std::size_t t, double x) const
  {
    return m_alpha[t] / s.U - s.P / (s.U * s.U) + s.K - s.U * m_c[t] / (x * x);
  }
  /// ∂²E/∂u_t² ≈ 2 U c_t / u_t³ (as Area_barrier_energy::curvatures).
  double curvature(const Sums& s, std::size_t t, double x) const { return 2 * s.U * m_c[t] / (x * x * x); }
  void derivatives(const std::vector<double>& u, std::vector<double>& dE) const
  {
    const Sums s = sums(u);
    dE.resize(u.size());
    for(std::size_t t = 0; t < u.size(); ++t) dE[t] = derivative(s, t, u[t]);
  }
  void curvatures(const std::vector<double>& u, std::vector<double>& w) const
  {
    const Sums s = sums(u);
    w.resize(u.size());
    for(std::size_t t = 0; t < u.size(); ++t) w[t] = curvature(s, t, u[t]);
  }
  /// a_t, face t's share of the target area.
  double share(std::size_t t) const { return m_a[t]; }

private:
  std::vector<double> m_a, m_alpha, m_c;
};

/// The opening's energy L = Σ w_t (log r_t)², w_t = A_t / Σ A and r_t as
/// above. Its gradient ∂L/∂u_t = 2 (w_t log r_t − u_t Σ_s w_s log r_s / U) / u_t
/// weighs a face by its log ratio where E's weighs it by 1/r_t: far from
/// the targets the Sobolev gradient of E spends each step on its few
/// smallest faces, that of L moves every face by its own ratio.
class Log_ratio_energy
{
public:
  explicit Log_ratio_energy(const Area_barrier_energy& barrier) : m_w(barrier.size())
  {
    for(std::size_t t = 0; t < m_w.size(); ++t) m_w[t] = std::sqrt(barrier.weight(t));
  }
  /// L(u), +∞ when a face is not positive.
  double value(const std::vector<double>& u) const
  {
    double U = 0;
    for(double x : u) {
      if(!(x > 0)) return std::numeric_limits<double>::infinity();
      U += x;
    }
    double L = 0;
    for(std::size_t t = 0; t < u.size(); ++t) {
      const double l = std::log(u[t] / (U * m_w[t]));
      L += m_w[t] * l * l;
    }
    return L;
  }
  /// ∂L/∂u_t for every face (u all positive).
  void derivatives(const std::vector<double>& u, std::vector<double>& dL) const
  {
    double U = 0, S = 0;
    for(double x : u) U += x;
    dL.resize(u.size());
    for(std::size_t t = 0; t < u.size(); ++t) {
      const double wl = m_w[t] * std::log(u[t] / (U * m_w[t]));
      S += wl;
      dL[t] = 2 * wl / u[t];
    }
    for(double& x : dL) x -= 2 * S / U;
  }
private:
  std::vector<double> m_w;
};

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
