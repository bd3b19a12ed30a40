#include "pred/linear_crossing.h"

#include <algorithm>
#include <cmath>

#include "arith/interval.h"
#include "poly/rational_root.h"
#include "pred/features.h"

namespace pccd::pred {

namespace {

using arith::Interval;

int certain_sign(const Interval &x) { return x.lo > 0 ? 1 : x.hi < 0 ? -1 : 0; }

struct I3 {
  Interval x, y, z;
};
I3 operator-(const I3 &a, const I3 &b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
I3 cross(const I3 &a, const I3 &b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
Interval dot(const I3 &a, const I3 &b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

// Point i's positions over T: x0 + T (x1 - x0), enclosed.
I3 position(const double *p0, const double *p1, int i, const Interval &T) {
  const double *a = p0 + 3 * i, *b = p1 + 3 * i;
  auto at = [&](int k) { return Interval(a[k]) + T * (Interval(b[k]) - Interval(a[k])); };
  return {at(0), at(1), at(2)};
}

// The cubic's true Bernstein coefficients as intervals (the middle ones were times 3).
void coefficients(const Cubic_bernstein &f, Interval c[4]) {
  for (int k = 0; k < 4; ++k) {
    c[k] = Interval(arith::round_down(f.value[k] - f.bound[k]), arith::round_up(f.value[k] + f.bound[k]));
    if (k == 1 || k == 2) c[k] = c[k] / Interval(3.0);
  }
}

// f(t) by de Casteljau on the enclosed coefficients (t a double in [0, 1]).
Interval eval(const Interval c[4], double t) {
  const Interval T(t), U = Interval(1.0) - T;
  Interval b[4] = {c[0], c[1], c[2], c[3]};
  for (int r = 1; r < 4; ++r)
    for (int k = 0; k + r < 4; ++k) b[k] = U * b[k] + T * b[k + 1];
  return b[0];
}

// A floating-point estimate of the root (bisection on the approximate coefficients);
// any value in [0, 1] is safe: it only chooses where the certificate is tried.
double estimate_root(const Cubic_bernstein &f) {
  const double v[4] = {f.value[0], f.value[1] / 3, f.value[2] / 3, f.value[3]};
  auto at = [&](double t) {
    double b[4] = {v[0], v[1], v[2], v[3]};
    for (int r = 1; r < 4; ++r)
      for (int k = 0; k + r < 4; ++k) b[k] = (1 - t) * b[k] + t * b[k + 1];
    return b[0];
  };
  double lo = 0, hi = 1;
  const bool neg_at_lo = v[0] < 0;
  for (int i = 0; i < 60 && hi - lo > 0x1p-50; ++i) {
    const double m = 0.5 * (lo + hi);
    if ((at(m) < 0) == neg_at_lo) lo = m; else hi = m;
  }
  return 0.5 * (lo + hi);
}

// The side conditions over T, each as a certain sign (0: not certain): vertex-face g_0,
// g_1, g_2; edge-edge s(b0), s(b1), s(a0), s(a1) (linear_crossing.h).
struct Sides {
  int s[4] = {0, 0, 0, 0};
};
Sides sides_on(int kind, const double *p0, const double *p1, const Interval &T) {
  const I3 x0 = position(p0, p1, 0, T), x1 = position(p0, p1, 1, T), x2 = position(p0, p1, 2, T),
           x3 = position(p0, p1, 3, T);
  Sides out;
  if (kind == VERTEX_FACE) {  // v = x0, triangle x1 x2 x3
    const I3 f[3] = {x1, x2, x3};
    const I3 n = cross(x2 - x1, x3 - x1);
    for (int i = 0; i < 3; ++i) out.s[i] = certain_sign(dot(n, cross(f[(i + 1) % 3] - f[i], x0 - f[i])));
    return out;
  }
  // edge-edge: a0 = x0, a1 = x1, b0 = x2, b1 = x3
  const I3 ea = x1 - x0, eb = x3 - x2, n = cross(ea, eb);
  out.s[0] = certain_sign(dot(n, cross(ea, x2 - x0)));
  out.s[1] = certain_sign(dot(n, cross(ea, x3 - x0)));
  out.s[2] = certain_sign(dot(n, cross(eb, x0 - x2)));
  out.s[3] = certain_sign(dot(n, cross(eb, x1 - x2)));
  return out;
}

// Some side condition certainly says "apart" on all of T.
bool apart(int kind, const Sides &d) {
  if (kind == VERTEX_FACE) return d.s[0] < 0 || d.s[1] < 0 || d.s[2] < 0;
  return d.s[0] * d.s[1] > 0 || d.s[2] * d.s[3] > 0;
}

// Every side condition certainly says "inside" on all of T.
bool inside(int kind, const Sides &d) {
  if (kind == VERTEX_FACE) return d.s[0] > 0 && d.s[1] > 0 && d.s[2] > 0;
  return d.s[0] * d.s[1] < 0 && d.s[2] * d.s[3] < 0;
}

// f's only root in [0, 1] and a bracket [ta, tb] of it with certainly opposite signs of
// f at its ends (c: the enclosed coefficients); false when the Descartes part fails or no
// bracket certifies.
bool single_root_bracket(const Cubic_bernstein &f, Interval c[4], double &ta, double &tb) {
  coefficients(f, c);
  int changes = 0;
  for (int k = 0; k < 4; ++k) {
    if (certain_sign(c[k]) == 0) return false;
    if (k > 0 && certain_sign(c[k]) != certain_sign(c[k - 1])) ++changes;
  }
  if (changes != 1) return false;
  const double r = estimate_root(f);
  // The narrowest bracket whose ends certainly differ in sign (f's enclosure error
  // sets how narrow it can be).
  for (double h : {0x1p-40, 0x1p-28, 0x1p-16, 0x1p-6}) {
    ta = r - h > 0 ? r - h : 0.0;
    tb = r + h < 1 ? r + h : 1.0;
    if (certain_sign(eval(c, ta)) * certain_sign(eval(c, tb)) < 0) return true;
  }
  return false;
}


// The number of halvings of [0, 1] the solver's bisection makes at tolerance tol: the
// least k >= 0 with 2^-k <= tol (it stops once hi - lo <= tol; the widths are 2^-k).
// Cached per thread: a config's tolerance rarely changes between calls.
int halvings(const arith::Rational &tol) {
  thread_local arith::Rational last(-1);
  thread_local int k = 0;
  if (tol == last) return k;
  k = 0;
  arith::Rational w(1);
  // tol > 0 (validated by the API). The cap is never reached in effect: the double
  // bisection stops near widths of 2^-53 (exact_midpoint) and leaves the rest to the solver.
  while (w > tol && k < 4000) {
    w /= 2;
    ++k;
  }
  last = tol;
  return k;
}

// x mod P for x = M 2^E (a finite double) times 2^-emin, emin <= E: an integer.
long mod_scaled(double x, int emin, long P) {
  if (x == 0) return 0;
  int e;
  const double fr = std::frexp(x, &e);             // x = fr 2^e, 0.5 <= |fr| < 1
  const long long M = static_cast<long long>(std::ldexp(fr, 53));  // exact: 53 bits
  long v = static_cast<long>(((M % P) + P) % P);
  long b = 2, r = 1;
  for (int n = e - 53 - emin; n > 0; n >>= 1, b = b * b % P)
    if (n & 1) r = r * b % P;
  return v * r % P;
}

// The cubic of features.h (VERTEX_FACE: det(f1 - f0, f2 - f0, v - f0); EDGE_EDGE:
// det(a1 - a0, b0 - a0, b1 - a0)) certainly has no rational root. With every coordinate
// scaled by 2^-emin (emin: the least exponent of their 53-bit integer mantissas) the
// cubic G has integer coefficients, and G mod P is computed from the coordinates mod P.
// A rational root p/q in lowest terms has q | lc(G), so for P not dividing the cubic
// coefficient (then deg G = 3 and P does not divide lc(G)), p q^-1 is a root mod P; a
// prime with no root mod P excludes rational roots. G is an integer multiple u F of the
// solver's primitive polynomial F with P not dividing u, so this answers "irrational"
// only when the solver's own test (pred/solve.cpp, poly::may_have_rational_root, the
// same primes) does too: the answers and stages agree.
bool cubic_irrational_roots(int kind, const double *p0, const double *p1) {
  int emin = 1 << 20;
  for (const double *p : {p0, p1})
    for (int i = 0; i < 12; ++i)
      if (p[i] != 0) {
        int e;
        std::frexp(p[i], &e);
        emin = std::min(emin, e - 53);
      }
  if (emin == 1 << 20) return false;  // every coordinate zero
  // The difference vectors (u, v, w) of the determinant as point indices (minuend,
  // subtrahend): VERTEX_FACE points v f0 f1 f2, EDGE_EDGE a0 a1 b0 b1.
  static const int vf[3][2] = {{2, 1}, {3, 1}, {0, 1}}, ee[3][2] = {{1, 0}, {2, 0}, {3, 0}};
  const int(*d)[2] = kind == VERTEX_FACE ? vf : ee;
  for (const unsigned long up : poly::kModularPrimes) {
    const long P = static_cast<long>(up);
    // Each difference vector component as a + b t mod P.
    long a[3][3], b[3][3];
    for (int r = 0; r < 3; ++r)
      for (int x = 0; x < 3; ++x) {
        const int i = d[r][0], j = d[r][1];
        const long u0 = (mod_scaled(p0[3 * i + x], emin, P) - mod_scaled(p0[3 * j + x], emin, P) + P) % P;
        const long u1 = (mod_scaled(p1[3 * i + x], emin, P) - mod_scaled(p1[3 * j + x], emin, P) + P) % P;
        a[r][x] = u0;
        b[r][x] = (u1 - u0 + P) % P;
      }
    // det by cofactors along row 0, polynomials in t of degree <= 3 mod P.
    auto mul = [P](const long *x, int nx, const long *y, int ny, long *z) {
      for (int i = 0; i < nx + ny - 1; ++i) z[i] = 0;
      for (int i = 0; i < nx; ++i)
        for (int j = 0; j < ny; ++j) z[i + j] = (z[i + j] + x[i] * y[j]) % P;
    };
    long g[4] = {0, 0, 0, 0};
    for (int x = 0; x < 3; ++x) {
      const int y = (x + 1) % 3, z = (x + 2) % 3;
      const long r1y[2] = {a[1][y], b[1][y]}, r2z[2] = {a[2][z], b[2][z]};
      const long r1z[2] = {a[1][z], b[1][z]}, r2y[2] = {a[2][y], b[2][y]};
      long p1q[3], p2q[3], minor[3], term[4];
      mul(r1y, 2, r2z, 2, p1q);
      mul(r1z, 2, r2y, 2, p2q);
      for (int k = 0; k < 3; ++k) minor[k] = (p1q[k] - p2q[k] + P) % P;
      const long r0x[2] = {a[0][x], b[0][x]};
      mul(r0x, 2, minor, 3, term);
      for (int k = 0; k < 4; ++k) g[k] = (g[k] + term[k]) % P;
    }
    if (g[3] == 0) continue;
    bool root = false;
    for (long t = 0; t < P && !root; ++t) root = ((g[3] * t + g[2]) % P * t + g[1]) % P * t % P == (P - g[0]) % P;
    if (!root) return true;
  }
  return false;
}
}  // namespace

bool crossing_misses(int kind, const double *p0, const double *p1, const Cubic_bernstein &f) {
  if (!f.ok || (kind != VERTEX_FACE && kind != EDGE_EDGE)) return false;
  Interval c[4];
  double ta, tb;
  return single_root_bracket(f, c, ta, tb) && apart(kind, sides_on(kind, p0, p1, Interval(ta, tb)));
}

bool crossing_hit(int kind, const double *p0, const double *p1, const Cubic_bernstein &f,
                  const Solve_options &opt, Contact_result &out) {
  Interval c[4];
  double ta, tb;
  if (!f.ok || !single_root_bracket(f, c, ta, tb) || !inside(kind, sides_on(kind, p0, p1, Interval(ta, tb))))
    return false;
  double lo = 0, hi = 1;
  if (opt.want_time) {
    // The solver's midpoint bisection (poly/earliest.h) with its decisions: the only
    // contact r is <= m exactly when f(m) has not f(0)'s sign (f(m) = 0 is left to the
    // solver, as is any uncertain sign). The widths are powers of two, compared exactly.
    const int s0 = certain_sign(c[0]);
    for (int k = halvings(opt.tol); k > 0; --k) {
      double m;
      if (!arith::exact_midpoint(lo, hi, m)) return false;  // the solver goes on exactly
      const int s = certain_sign(eval(c, m));
      if (s == 0) return false;
      if (s != s0) hi = m; else lo = m;
    }
    // f(hi) != 0 (hi = 1 or a point of certain sign): r is inside, not exactly hi. The
    // solver then proves r irrational or searches for a rational r.
    if (opt.want_exact && !cubic_irrational_roots(kind, p0, p1)) return false;
  }
  out.collides = true;
  out.exact = false;
  out.lo = lo;
  out.hi = hi;
  out.features.assign(1, Feature{kind, {{0, 1, 2, 3}}});
  out.stage = STAGE_INTERVAL;
  return true;
}

}  // namespace pccd::pred
