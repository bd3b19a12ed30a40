// Point trajectories: each coordinate a polynomial of t (rigid-body motions, with
// their rational rotation, will build these too: see the paper, appendix A).
// Vectors of polynomials with the products the contact conditions need.
#pragma once
#include <array>

#include "poly/poly.h"

namespace pccd::motion {

using poly::Poly;

template <class NT>
struct Vec3p {
  std::array<Poly<NT>, 3> v;
  const Poly<NT> &operator[](int i) const { return v[i]; }
  Poly<NT> &operator[](int i) { return v[i]; }
};

template <class NT>
Vec3p<NT> operator-(const Vec3p<NT> &a, const Vec3p<NT> &b) {
  return {{a[0] - b[0], a[1] - b[1], a[2] - b[2]}};
}
// Both by poly::signed_products: exact inputs in one integer convolution each.
template <class NT>
Poly<NT> cross_component(const Vec3p<NT> &a, const Vec3p<NT> &b, int i, int j) {  // a_i b_j - a_j b_i
  const Poly<NT> *x[2] = {&a[i], &a[j]}, *y[2] = {&b[j], &b[i]};
  const int sign[2] = {1, -1};
  return poly::signed_products(x, y, sign, 2);
}
template <class NT>
Vec3p<NT> cross(const Vec3p<NT> &a, const Vec3p<NT> &b) {
  return {{cross_component(a, b, 1, 2), cross_component(a, b, 2, 0), cross_component(a, b, 0, 1)}};
}
template <class NT>
Poly<NT> dot(const Vec3p<NT> &a, const Vec3p<NT> &b) {
  const Poly<NT> *x[3] = {&a[0], &a[1], &a[2]}, *y[3] = {&b[0], &b[1], &b[2]};
  const int sign[3] = {1, 1, 1};
  return poly::signed_products(x, y, sign, 3);
}

// A point trajectory is a Vec3p: p(t) = (x(t), y(t), z(t)).
template <class NT>
using Point_traj = Vec3p<NT>;

template <class NT>
Point_traj<NT> convert_traj(const Point_traj<arith::Rational> &p) {
  return {{poly::convert<NT>(p[0]), poly::convert<NT>(p[1]), poly::convert<NT>(p[2])}};
}

}  // namespace pccd::motion
