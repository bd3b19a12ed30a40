// poly::rational_first_contact (lib/poly/rational_root.h) on systems whose first root in
// (lo, hi) is known by construction: rational (reported exactly), irrational (not), a
// double root (the square-free path), a contact at hi itself, and sublevel systems. Each
// f also has a rational root outside (lo, hi), so the modular test cannot prove an
// irrational root irrational and the isolation decides. Two of its shortcuts are met on
// the way: a simple root alone in (lo, hi) (values of opposite signs at the ends, f'
// of one sign) takes f itself for its square-free part, and f(hi) != 0 skips the count
// of contacts in (lo, hi); the answers must be those of the definitions.
#include "poly/rational_root.h"

#include "expect.h"

using pccd::arith::Rational;
using pccd::poly::Poly;
using pccd::poly::rational_first_contact;
using System = pccd::poly::System<Rational>;

namespace {

// n / d in lowest terms (mpq_class(n, d) is not canonicalized by itself).
Rational q(long n, long d) {
  Rational r(n, d);
  r.canonicalize();
  return r;
}

Poly<Rational> P(std::vector<Rational> c) { return Poly<Rational>(std::move(c)); }
Poly<Rational> lin(const Rational &r) { return Poly<Rational>::linear_root(r); }  // t - r

System roots(Poly<Rational> f, std::vector<Poly<Rational>> g = {}) {
  System s;
  s.kind = System::Kind::roots;
  s.f = std::move(f);
  s.g = std::move(g);
  return s;
}

// The answer for one system on (lo, hi): exact with t, or not exact.
void check(const System &s, const Rational &lo, const Rational &hi, bool exact, const Rational &t,
           const char *what) {
  const pccd::poly::Rational_root_result r = rational_first_contact({s}, {0}, lo, hi);
  expect(r.exact == exact, std::string(what) + ": exact");
  if (exact) expect(r.t == t && r.which.size() == 1, std::string(what) + ": the time");
}

}  // namespace

int main() {
  const Rational third = q(1, 3), lo = q(33, 100), hi = q(34, 100);
  // (t - 1/3)(t - 3/4)(t - 1/5): a simple rational root in (lo, hi).
  const Poly<Rational> f1 = lin(third) * lin(q(3, 4)) * lin(q(1, 5));
  check(roots(f1), lo, hi, true, third, "simple rational root");
  // The same times 7/5 with a constraint positive there: the same answer.
  check(roots(q(7, 5) * f1, {P({Rational(1), Rational(1)})}), lo, hi, true, third,
        "scaled, constrained");
  // (t^2 - 1/8)(t - 3/4): the irrational root sqrt(1/8) = 0.35355... alone in (0.35, 0.36).
  const Poly<Rational> f2 = P({q(-1, 8), Rational(0), Rational(1)}) * lin(q(3, 4));
  check(roots(f2), q(35, 100), q(36, 100), false, Rational(0), "irrational root");
  // Three roots in (lo, hi), the first irrational (sqrt(0.10923) = 0.33050...), then 1/3
  // and 0.3399 (near hi, where a secant from the ends would go): a sign change at the
  // ends, but f' changes sign too, so not the simple path.
  const Poly<Rational> f4 = P({q(-10923, 100000), Rational(0), Rational(1)}) * lin(third) * lin(q(3399, 10000));
  check(roots(f4), lo, hi, false, Rational(0), "three roots, the first irrational");
  // A double root at 1/3: not simple, the square-free path finds it exactly.
  const Poly<Rational> f3 = lin(third) * lin(third) * lin(q(3, 4));
  check(roots(f3), lo, hi, true, third, "double rational root");
  // A contact at hi itself: f(hi) = 0 and no root inside.
  check(roots(lin(hi) * lin(q(3, 4))), lo, hi, true, hi, "root at hi");
  // A root inside that the constraint refuses, and one at hi it accepts: the answer is
  // hi (count_open is 0 inside). g = t - 0.335 is negative at 1/3 and positive at hi.
  check(roots(lin(third) * lin(hi), {lin(q(335, 1000))}), lo, hi, true, hi, "refused inside");
  // Sublevel (f <= 0): first at the rational crossing 1/3, and at the irrational one.
  System sub;
  sub.kind = System::Kind::sublevel;
  sub.f = lin(third) * lin(q(3, 4));  // > 0 before 1/3, < 0 after (up to 3/4)
  check(sub, lo, hi, true, third, "sublevel, rational");
  sub.f = f2;  // (t^2 - 1/8)(t - 3/4): > 0 before sqrt(1/8), < 0 after (up to 3/4)
  check(sub, q(35, 100), q(36, 100), false, Rational(0), "sublevel, irrational");
  // Two systems: the rational one first wins; an irrational one before it makes the
  // time irrational.
  {
    const std::vector<System> two{roots(f1), roots(lin(q(339, 1000)) * lin(q(3, 4)))};
    const pccd::poly::Rational_root_result r = rational_first_contact(two, {0, 1}, lo, hi);
    expect(r.exact && r.t == third && r.which == std::vector<size_t>{0}, "two systems: 1/3 first");
    const std::vector<System> early{roots(f2), roots(lin(q(355, 1000)) * lin(q(3, 4)))};
    const pccd::poly::Rational_root_result e =
        rational_first_contact(early, {0, 1}, q(35, 100), q(36, 100));
    expect(!e.exact, "an irrational root before the rational one");
  }
  std::printf("%ld passed, %ld failed\n", passed, failed);
  return failed != 0;
}
