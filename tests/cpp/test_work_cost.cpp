// Work counted by cost (util::work_cost, issue 23): one exact operation on long numbers
// checks the limits inside itself, so a limit holds even when a single polynomial
// product takes minutes; the count is a function of the operands (the same twice, and
// growing with their sizes); the values are those of plain rational arithmetic.
// Prints "N passed, N failed".
#include <chrono>
#include <cstdio>
#include <gmpxx.h>
#include <vector>

#include "poly/poly.h"
#include "util/work_budget.h"

using pccd::arith::Rational;
using pccd::poly::Poly;
using pccd::util::Budget_scope;
using pccd::util::Limit_reached;
using pccd::util::Work_budget;
using pccd::util::Work_limits;

static long passed = 0, failed = 0;
#define CHECK(c) ((c) ? (void)++passed : (void)(++failed, std::printf("FAIL %s:%d: %s\n", __FILE__, __LINE__, #c)))

// A polynomial of degree deg whose coefficients are fractions of two random numbers of
// `bits` bits each: distinct denominators make the common denominator of the product
// deg * bits long, the slow case of issue 23 (30-digit rationals, degree 48).
static Poly<Rational> random_poly(gmp_randclass &rng, int deg, unsigned long bits) {
  std::vector<Rational> c;
  for (int i = 0; i <= deg; ++i) {
    mpz_class num = rng.get_z_bits(bits), den = rng.get_z_bits(bits) + 1;
    Rational x(num, den);
    x.canonicalize();
    c.push_back(x);
  }
  return Poly<Rational>(std::move(c));
}

// Horner with canonical fractions at every step: the value the integer paths must give.
static Rational horner(const Poly<Rational> &p, const Rational &t) {
  Rational r = 0;
  for (size_t i = p.c.size(); i-- > 0;) r = r * t + p.c[i];
  return r;
}

static double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// The steps one product counts under a budget without a limit.
static std::uint64_t steps_of_product(const Poly<Rational> &a, const Poly<Rational> &b) {
  Work_limits none;
  none.max_steps = ~std::uint64_t(0);
  Work_budget budget(none);
  Budget_scope scope(&budget);
  const Poly<Rational> c = a * b;
  CHECK(c.degree() == a.degree() + b.degree());
  return budget.steps();
}

int main() {
  gmp_randclass rng(gmp_randinit_default);
  rng.seed(23);

  // Values: a product and an evaluation in integers equal plain rational arithmetic.
  {
    const Poly<Rational> a = random_poly(rng, 9, 200), b = random_poly(rng, 7, 150);
    const Rational t(mpz_class(-37), mpz_class(1000003));
    CHECK((a * b).eval(t) == horner(a, t) * horner(b, t));
    CHECK(a.eval(t) == horner(a, t));
    CHECK(a.eval(Rational(0)) == a.c[0]);
    CHECK(Poly<Rational>().eval(t) == 0);
  }

  // The count is a function of the operands, and grows with their sizes: the same
  // product counts the same steps twice; numbers 4 times as long count at least 8
  // times as many (an n-limb by m-limb operation costs n * m).
  {
    const Poly<Rational> a = random_poly(rng, 24, 2000), b = random_poly(rng, 24, 2000);
    const std::uint64_t s1 = steps_of_product(a, b), s2 = steps_of_product(a, b);
    CHECK(s1 == s2);
    CHECK(s1 > 1);  // a single product counts by its cost, not as one step
    const Poly<Rational> A = random_poly(rng, 24, 8000), B = random_poly(rng, 24, 8000);
    CHECK(steps_of_product(A, B) >= 8 * s1);
    std::printf("steps of a degree-24 product: %llu (2,000-bit fractions), %llu (8,000-bit)\n",
                (unsigned long long)s1, (unsigned long long)steps_of_product(A, B));
  }

  // One step made long on purpose: a product of two degree-64 polynomials of
  // 20,000-bit fractions (a common denominator of 1.3 million bits, minutes of GMP
  // work) under max_seconds = 0.3 ends with Limit_reached well within a second; so
  // does the evaluation at a time of 60,000 bits, and a cancellation.
  {
    const Poly<Rational> a = random_poly(rng, 64, 20000), b = random_poly(rng, 64, 20000);
    for (int which = 0; which < 3; ++which) {
      pccd::util::Cancel_flag cancel;
      Work_limits lim;
      if (which == 2) {
        cancel.set();
        lim.cancel = &cancel;
      } else {
        lim.max_seconds = 0.3;
      }
      const auto t0 = std::chrono::steady_clock::now();
      bool stopped = false;
      try {
        Work_budget budget(lim);
        Budget_scope scope(&budget);
        if (which == 1) {
          const Rational t(mpz_class(1), (mpz_class(1) << 60000) + 1);
          (void)(a * a).eval(t);
        } else {
          (void)(a * b);
        }
      } catch (const Limit_reached &e) {
        stopped = e.which == (which == 2 ? Limit_reached::CANCEL : Limit_reached::SECONDS);
      }
      const double s = seconds_since(t0);
      std::printf("case %d: stopped after %.3f s\n", which, s);
      CHECK(stopped);
      CHECK(s < (which == 2 ? 0.5 : 1.5));
    }
  }

  std::printf("%ld passed, %ld failed\n", passed, failed);
  return failed ? 1 : 0;
}
