#pragma once
/// @file Jet.hpp
/// Private helper of the element module: a forward-mode automatic-differentiation number carrying
/// a value, its gradient and (optionally) its Hessian with respect to N independent variables
/// (truncated Taylor arithmetic; Griewank & Walther 2008, "Evaluating Derivatives", ch. 13).
/// Fixed size, no heap allocation. Used to differentiate the co-rotational beam strain energy.

#include <array>
#include <cmath>

namespace tangle::element {

/// Truncated Taylor number of order 1 (value + gradient) or 2 (value + gradient + Hessian) in N
/// variables. The Hessian is stored packed (upper triangle, row by row: N (N + 1) / 2 entries).
template <int N, int Order>
class Jet {
  static_assert(N > 0 && (Order == 1 || Order == 2), "Jet: N > 0 and Order 1 or 2");

 public:
  static constexpr int kSize = N;                                   ///< number of variables
  static constexpr int kPacked = Order == 2 ? N * (N + 1) / 2 : 0;  ///< stored Hessian entries

  /// A constant (all derivatives zero).
  constexpr Jet(double value = 0.0) : m_value(value), m_grad{}, m_hess{} {}  // NOLINT: implicit on purpose

  /// The independent variable number `index` (0-based) at value `value`.
  static Jet variable(double value, int index) {
    Jet j(value);
    j.m_grad[index] = 1.0;
    return j;
  }

  double value() const { return m_value; }        ///< function value
  double grad(int i) const { return m_grad[i]; }  ///< d f / d x_i
  double& grad(int i) { return m_grad[i]; }       ///< d f / d x_i (writable, to seed)
  /// d^2 f / (d x_i d x_j), symmetric; 0 for a first-order jet.
  double hess(int i, int j) const {
    if constexpr (Order == 2) {
      return i <= j ? m_hess[packedIndex(i, j)] : m_hess[packedIndex(j, i)];
    } else {
      (void)i;
      (void)j;
      return 0.0;
    }
  }

  /// Chain rule for a scalar function f applied to this jet, given f(v), f'(v), f''(v).
  Jet chain(double f0, double f1, double f2) const {
    Jet r(f0);
    for (int i = 0; i < N; ++i) r.m_grad[i] = f1 * m_grad[i];
    if constexpr (Order == 2) {
      int k = 0;
      for (int i = 0; i < N; ++i) {
        const double gi = f2 * m_grad[i];
        for (int j = i; j < N; ++j, ++k) r.m_hess[k] = f1 * m_hess[k] + gi * m_grad[j];
      }
    } else {
      (void)f2;
    }
    return r;
  }

  Jet& operator+=(const Jet& b) {
    m_value += b.m_value;
    for (int i = 0; i < N; ++i) m_grad[i] += b.m_grad[i];
    for (int k = 0; k < kPacked; ++k) m_hess[k] += b.m_hess[k];
    return *this;
  }
  Jet& operator-=(const Jet& b) {
    m_value -= b.m_value;
    for (int i = 0; i < N; ++i) m_grad[i] -= b.m_grad[i];
    for (int k = 0; k < kPacked; ++k) m_hess[k] -= b.m_hess[k];
    return *this;
  }
  Jet& operator*=(double s) {
    m_value *= s;
    for (int i = 0; i < N; ++i) m_grad[i] *= s;
    for (int k = 0; k < kPacked; ++k) m_hess[k] *= s;
    return *this;
  }
  /// this += s * x (fused, no temporary).
  Jet& addScaled(const Jet& x, double s) {
    m_value += s * x.m_value;
    for (int i = 0; i < N; ++i) m_grad[i] += s * x.m_grad[i];
    for (int k = 0; k < kPacked; ++k) m_hess[k] += s * x.m_hess[k];
    return *this;
  }
  /// Adds `a` to the symmetric Hessian pair (i, j) (i.e. to d^2f/dx_i dx_j and d^2f/dx_j dx_i; a
  /// diagonal entry i == j receives `a` once).
  void addHess(int i, int j, double a) requires(Order == 2) {
    m_hess[i <= j ? packedIndex(i, j) : packedIndex(j, i)] += a;
  }

  Jet& operator+=(double s) {
    m_value += s;
    return *this;
  }
  Jet& operator-=(double s) {
    m_value -= s;
    return *this;
  }

  /// Product rule: (ab)'' = a b'' + b a'' + a' b'^T + b' a'^T.
  friend Jet operator*(const Jet& a, const Jet& b) {
    Jet r(a.m_value * b.m_value);
    for (int i = 0; i < N; ++i) r.m_grad[i] = a.m_value * b.m_grad[i] + b.m_value * a.m_grad[i];
    if constexpr (Order == 2) {
      int k = 0;
      for (int i = 0; i < N; ++i) {
        const double ai = a.m_grad[i];
        const double bi = b.m_grad[i];
        for (int j = i; j < N; ++j, ++k) {
          r.m_hess[k] =
              a.m_value * b.m_hess[k] + b.m_value * a.m_hess[k] + ai * b.m_grad[j] + bi * a.m_grad[j];
        }
      }
    }
    return r;
  }

  friend Jet operator+(Jet a, const Jet& b) { return a += b; }
  friend Jet operator-(Jet a, const Jet& b) { return a -= b; }
  friend Jet operator-(Jet a) { return a *= -1.0; }
  friend Jet operator*(Jet a, double s) { return a *= s; }
  friend Jet operator*(double s, Jet a) { return a *= s; }
  friend Jet operator+(Jet a, double s) { return a += s; }
  friend Jet operator-(Jet a, double s) { return a -= s; }

 private:
  static constexpr int packedIndex(int i, int j) { return i * N - i * (i - 1) / 2 + (j - i); }

  double m_value;
  std::array<double, N> m_grad;
  std::array<double, kPacked> m_hess;
};

/// Value of a plain double (generic code over double and Jet).
inline double valueOf(double x) { return x; }
/// Value of a jet.
template <int N, int Order>
double valueOf(const Jet<N, Order>& x) {
  return x.value();
}

/// Chain rule on a plain double: only the value f0 is used.
inline double chainRule(double /*x*/, double f0, double /*f1*/, double /*f2*/) { return f0; }
/// Chain rule on a jet with f(x), f'(x), f''(x) evaluated at the jet's value.
template <int N, int Order>
Jet<N, Order> chainRule(const Jet<N, Order>& x, double f0, double f1, double f2) {
  return x.chain(f0, f1, f2);
}

/// Square root of a jet (value > 0).
template <int N, int Order>
Jet<N, Order> sqrt(const Jet<N, Order>& x) {
  const double s = std::sqrt(x.value());
  return x.chain(s, 0.5 / s, -0.25 / (s * x.value()));
}

/// Reciprocal 1/x of a plain double.
inline double reciprocal(double x) { return 1.0 / x; }
/// Reciprocal 1/x of a jet (value != 0).
template <int N, int Order>
Jet<N, Order> reciprocal(const Jet<N, Order>& x) {
  const double r = 1.0 / x.value();
  return x.chain(r, -r * r, 2.0 * r * r * r);
}

}  // namespace tangle::element
