#pragma once
// Globally adaptive Gauss–Kronrod quadrature (the 7-point Gauss rule inside the 15-point
// Kronrod rule, as QUADPACK's QAG with QK15: Piessens et al., QUADPACK (1983)) of a real or
// complex function on finite intervals: the panel whose Kronrod and Gauss sums differ most is
// halved until the sum of those differences is below the tolerance, or `max_panels` panels.
#include <array>
#include <cmath>
#include <cstddef>
#include <queue>
#include <vector>

namespace rollnoise {

namespace gauss_kronrod_detail {
// Nodes of the Kronrod rule on [0, 1] (odd indices are the Gauss nodes) and weights.
inline constexpr std::array<double, 8> nodes{0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
                                             0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
                                             0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
                                             0.207784955007898467600689403773245, 0.0};
inline constexpr std::array<double, 8> kronrod{0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
                                               0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
                                               0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
                                               0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
inline constexpr std::array<double, 4> gauss{0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
                                             0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

template <class Value>
struct Panel {
  double a = 0.0, b = 0.0;
  Value value{};
  double error = 0.0;
  bool operator<(const Panel& other) const { return error < other.error; }
};

template <class F, class Value>
Panel<Value> panel(const F& f, double a, double b) {
  const double centre = 0.5 * (a + b), half = 0.5 * (b - a);
  const Value middle = f(centre);
  Value k = middle * kronrod[7];
  Value g = middle * gauss[3];
  for (int j = 0; j < 7; ++j) {
    const Value sum = f(centre - half * nodes[j]) + f(centre + half * nodes[j]);
    k += sum * kronrod[j];
    if (j % 2 == 1) g += sum * gauss[j / 2];
  }
  return {a, b, k * half, std::abs((k - g) * half)};
}
}  // namespace gauss_kronrod_detail

// ∫ f(x) dx over [breaks[0], breaks.back()] (breaks ascending, at least two: the integrand's
// awkward points), to about `tolerance` (absolute), for f returning double or
// std::complex<double>.
template <class F>
auto integrate_gauss_kronrod(const F& f, const std::vector<double>& breaks, double tolerance,
                             std::size_t max_panels = 4000) {
  using Value = decltype(f(breaks.front()));
  using gauss_kronrod_detail::Panel;
  std::priority_queue<Panel<Value>> panels;
  double error = 0.0;
  for (std::size_t j = 0; j + 1 < breaks.size(); ++j) {
    if (!(breaks[j + 1] > breaks[j])) continue;
    const Panel<Value> first = gauss_kronrod_detail::panel<F, Value>(f, breaks[j], breaks[j + 1]);
    error += first.error;
    panels.push(first);
  }
  while (!panels.empty() && error > tolerance && panels.size() < max_panels) {
    const Panel<Value> worst = panels.top();
    const double centre = 0.5 * (worst.a + worst.b);
    if (!(centre > worst.a && centre < worst.b)) break;  // no room left to halve
    panels.pop();
    const Panel<Value> left = gauss_kronrod_detail::panel<F, Value>(f, worst.a, centre);
    const Panel<Value> right = gauss_kronrod_detail::panel<F, Value>(f, centre, worst.b);
    error += left.error + right.error - worst.error;
    panels.push(left);
    panels.push(right);
  }
  Value sum{};
  while (!panels.empty()) {
    sum += panels.top().value;
    panels.pop();
  }
  return sum;
}

}  // namespace rollnoise
