// poly::signed_products (sum of sign_k a_k b_k in one integer convolution) and the
// motion layer's cross and dot built on it, against a schoolbook loop over Q written
// here (no library arithmetic on polynomials): random integer polynomials (zeros and
// empty ones among them), rational ones (the generic route), and cases built so that
// leading terms cancel (a b - b a = 0; a (c b) - (c a) b = 0; equal leading terms), where
// the result must come back trimmed. The random rounds run once without and once under
// a work budget (util/work_budget.h), which makes the product count its cost per row:
// a zero factor next to a nonzero one (empty result) once read past the result there.
// Prints "N passed, N failed".
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "motion/trajectory.h"
#include "poly/poly.h"
#include "util/work_budget.h"

using pccd::arith::Rational;
using pccd::motion::Vec3p;
using pccd::poly::Poly;

#include "expect.h"

// sum_k sign_k a_k b_k coefficient by coefficient in mpq, then trimmed.
static std::vector<Rational> oracle(const std::vector<const Poly<Rational> *> &a,
                                    const std::vector<const Poly<Rational> *> &b,
                                    const std::vector<int> &sign) {
  std::vector<Rational> r;
  for (size_t k = 0; k < a.size(); ++k)
    for (size_t i = 0; i < a[k]->c.size(); ++i)
      for (size_t j = 0; j < b[k]->c.size(); ++j) {
        if (r.size() < i + j + 1) r.resize(i + j + 1, Rational(0));
        Rational p = a[k]->c[i] * b[k]->c[j];
        if (sign[k] > 0) r[i + j] += p; else r[i + j] -= p;
      }
  while (!r.empty() && r.back() == 0) r.pop_back();
  return r;
}

static Poly<Rational> random_poly(std::mt19937_64 &rng, bool integer) {
  const int degree = int(rng() % 6) - 1;  // -1: the zero polynomial
  std::vector<Rational> c;
  for (int i = 0; i <= degree; ++i) {
    Rational x(pccd::arith::Integer(long(rng() % 2001) - 1000));
    if (rng() % 5 == 0) x = 0;
    x *= Rational(pccd::arith::Integer(1) << int(rng() % 120));  // long numbers too
    if (!integer) x /= long(rng() % 7 + 1);
    c.push_back(x);
  }
  return Poly<Rational>(std::move(c));
}

static void check(const std::vector<const Poly<Rational> *> &a,
                  const std::vector<const Poly<Rational> *> &b, const std::vector<int> &sign,
                  const std::string &what) {
  const Poly<Rational> r = pccd::poly::signed_products(a.data(), b.data(), sign.data(), a.size());
  expect(r.c == oracle(a, b, sign), what);
  for (const Rational &x : r.c) {  // canonical: lowest terms, positive denominator
    Rational y = x;
    y.canonicalize();
    expect(y.get_num() == x.get_num() && y.get_den() == x.get_den(), what + " canonical");
  }
}

int main() {
  std::mt19937_64 rng(34);
  pccd::util::Work_limits limits;
  limits.max_steps = std::uint64_t(1) << 60;  // never reached: only the counting matters
  pccd::util::Work_budget budget(limits);
  for (int round = 0; round < 800; ++round) {
    pccd::util::Budget_scope scope(round < 400 ? nullptr : &budget);
    const bool integer = round % 4 != 3;  // every fourth round: rationals (generic route)
    const size_t n = 1 + rng() % 3;
    std::vector<Poly<Rational>> x, y;
    for (size_t k = 0; k < n; ++k) {
      x.push_back(random_poly(rng, integer));
      y.push_back(random_poly(rng, integer));
    }
    std::vector<const Poly<Rational> *> a, b;
    std::vector<int> sign;
    for (size_t k = 0; k < n; ++k) {
      a.push_back(&x[k]);
      b.push_back(&y[k]);
      sign.push_back(rng() % 2 ? 1 : -1);
    }
    check(a, b, sign, "random round " + std::to_string(round));
    // Cancellation: a b - b a = 0 and a (c b) - (c a) b = 0 (the empty polynomial).
    const Poly<Rational> cb = y[0] * x[n - 1], ca = x[0] * x[n - 1];
    check({&x[0], &y[0]}, {&y[0], &x[0]}, {1, -1}, "a b - b a, round " + std::to_string(round));
    check({&x[0], &ca}, {&cb, &y[0]}, {1, -1}, "a (c b) - (c a) b, round " + std::to_string(round));
    const Poly<Rational> sum = pccd::poly::signed_products(std::vector<const Poly<Rational> *>{&x[0], &y[0]}.data(),
                                                           std::vector<const Poly<Rational> *>{&y[0], &x[0]}.data(),
                                                           std::vector<int>{1, -1}.data(), 2);
    expect(sum.c.empty(), "a b - b a is the zero polynomial, round " + std::to_string(round));
  }
  // Equal leading terms: (t^2 + 1)(t + 2) - (t^2)(t + 3) = -t^2 + t + 2: degree drops by one.
  const Poly<Rational> p(std::vector<Rational>{1, 0, 1}), q(std::vector<Rational>{2, 1}),
      s(std::vector<Rational>{0, 0, 1}), u(std::vector<Rational>{3, 1});
  const Poly<Rational> d = pccd::poly::signed_products(std::vector<const Poly<Rational> *>{&p, &s}.data(),
                                                       std::vector<const Poly<Rational> *>{&q, &u}.data(),
                                                       std::vector<int>{1, -1}.data(), 2);
  expect(d.c == std::vector<Rational>{2, 1, -1}, "leading terms cancel, degree 2 left");
  // cross and dot of random integer vectors against the oracle, component by component.
  for (int round = 0; round < 100; ++round) {
    Vec3p<Rational> a, b;
    for (int i = 0; i < 3; ++i) {
      a[i] = random_poly(rng, round % 2 == 0);
      b[i] = random_poly(rng, round % 2 == 0);
    }
    const Vec3p<Rational> c = pccd::motion::cross(a, b);
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3, k = (i + 2) % 3;  // c_i = a_j b_k - a_k b_j
      expect(c[i].c == oracle({&a[j], &a[k]}, {&b[k], &b[j]}, {1, -1}),
             "cross component " + std::to_string(i) + ", round " + std::to_string(round));
    }
    expect(pccd::motion::dot(a, b).c == oracle({&a[0], &a[1], &a[2]}, {&b[0], &b[1], &b[2]}, {1, 1, 1}),
           "dot, round " + std::to_string(round));
  }
  std::printf("%ld passed, %ld failed\n", passed, failed);
  return failed == 0 ? 0 : 1;
}
