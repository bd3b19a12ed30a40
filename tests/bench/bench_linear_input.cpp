// Workloads of bench_linear: the simulation-like generator and the public CSV reader.
//
// THE GENERATOR (`sim`). Query i of n (i even: vertex-face, i odd: edge-edge) is built
// around a (near) contact at a time tc, with draws from one std::mt19937_64(seed) (in
// the order of make_one below), where U(a, b) = a + (b - a) * (bits >> 11) * 2^-53 and
// LU(a, b) = a * (b / a)^U(0, 1) (log-uniform):
//   - the case: colliding with probability 0.022, else a near miss of one of three modes
//     with probability 1/3 each (below); about 6 % of the "over" misses touch after all
//     (the non-rigid part tilts the primitives into each other), so about 4 % of all
//     queries collide (measured and printed by bench_linear, per case);
//   - the place: a centre c uniform in [-1, 1]^3 (scene coordinates of order 1) and an
//     orthonormal frame (e1, e2, n): n a uniform random unit vector, e1 a uniform random
//     unit vector (redrawn while |e1 . n| > 0.99) made orthogonal to n, e2 = n x e1;
//   - tc ~ U(0, 1) (replaced by 1 for the "short" miss);
//   - primitive A (the face; edge a) has size s_A ~ LU(1e-2, 1) and moves by the
//     translation u_A = d_A * (uniform unit vector), d_A ~ LU(1e-3, 1e-1); primitive B
//     (the vertex; edge b; for edge b its own size s_B ~ LU(1e-2, 1)) moves by u_A + w,
//     where w, B's displacement relative to A, has length d ~ LU(1e-3, 1e-1) and the
//     direction cos(al) (-n) + sin(al) tau, tau a uniform unit vector in the plane (e1, e2)
//     and al ~ U(0, 60 deg) (B approaches A's plane from the +n side), al = 90 deg for
//     the "over" miss;
//   - near misses keep a gap g = d * LU(1e-2, 3) (a few displacement lengths at most);
//   - geometry AT TIME tc (positions Q_k):
//       vertex-face: the face f_k = c + s_A r_k (cos th_k e1 + sin th_k e2), k = 0, 1, 2,
//         th_k = 2 pi k / 3 + U(-0.4, 0.4), r_k ~ U(0.5, 1); a point P of the face with
//         barycentrics 0.1 / 3 + 0.9 b, b uniform on the simplex; the vertex at
//           colliding: P (it crosses the face at tc),
//           short:     P + g n at tc = 1 (it stops g above the face),
//           beside:    M + g o, M = f_k + U(0.05, 0.95) (f_k+1 - f_k) on a random side, o
//                      that side's outward unit normal in the plane (it crosses the plane
//                      g outside that side),
//           over:      P + g n, moving parallel to the face (al = 90 deg);
//       edge-edge: edge a along e1 through P = c, a0 = P - la s_A e1, a1 = P + (1 - la)
//         s_A e1, la ~ U(0.05, 0.95); edge b along bd = cos(be) e1 + sin(be) e2,
//         be ~ U(20, 160) deg, b0 = P + o - lb s_B bd, b1 = b0 + s_B bd, lb ~ U(0.05, 0.95),
//         with o = 0 (colliding: the edges cross at tc), g n at tc = 1 (short), 0 but
//         lb = -g / s_B (beside: b's end b0 passes g from a's line along bd) or g n with
//         al = 90 deg (over);
//   - motion of each point k of a primitive P (A or B) with centroid z_P (at tc) and
//     size s_P: D_k = u_P + phi_P ax_P x (Q_k - z_P) + del_k with u_P = u_A for A and
//     u_A + w for B, a small rotation linearised (ax_P a uniform unit axis, phi_P =
//     U(0, 0.2) d / s_P, so it moves points by at most 0.2 d) plus a deformation del_k
//     uniform in the ball of radius 0.05 d; then p_t0 = Q_k - tc D_k and p_t1 = Q_k +
//     (1 - tc) D_k (so p_t1 = p_t0 + D_k up to rounding). The non-rigid parts scale with
//     the RELATIVE displacement d, not with d_A: the common translation u_A is the
//     motion of the whole neighbourhood (a falling cloth, a sliding body).
// All arithmetic is in doubles; the resulting doubles ARE the query (taken exactly). The
// rotation and deformation can turn a near miss into a contact and back, so the fraction
// that collides is measured by polyccd's exact answer (bench_linear prints it).
#include "bench_linear_input.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

namespace bench {
namespace {

struct V3 {
  double x, y, z;
};
V3 operator+(V3 a, V3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
V3 operator-(V3 a, V3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
V3 operator*(double s, V3 a) { return {s * a.x, s * a.y, s * a.z}; }
double dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V3 cross(V3 a, V3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
V3 unit(V3 a) { return (1.0 / std::sqrt(dot(a, a))) * a; }

const double kPi = 3.14159265358979323846;
const double kDeg = kPi / 180.0;
// Probability of the colliding case; with the "over" misses that touch, ~4 % collide.
const double kColliding = 0.022;

class Rng {
 public:
  explicit Rng(std::uint64_t seed) : g_(seed) {}
  double u(double a, double b) { return a + (b - a) * static_cast<double>(g_() >> 11) * 0x1p-53; }
  double log_u(double a, double b) { return a * std::pow(b / a, u(0, 1)); }
  V3 in_ball() {  // uniform in the unit ball (rejection from the cube)
    for (;;) {
      V3 p{u(-1, 1), u(-1, 1), u(-1, 1)};
      double r2 = dot(p, p);
      if (r2 <= 1 && r2 > 1e-12) return p;
    }
  }
  V3 direction() { return unit(in_ball()); }

 private:
  std::mt19937_64 g_;
};

enum class Case { colliding, short_, beside, over };
const char *case_name(Case c) {
  switch (c) {
    case Case::colliding: return "colliding";
    case Case::short_: return "miss: short";
    case Case::beside: return "miss: beside";
    case Case::over: return "miss: over";
  }
  return "?";
}

// The points of one primitive at tc and how it moves (see the header comment).
struct Primitive {
  std::vector<V3> q;  // positions at tc
  V3 u;               // translation
  double d;           // displacement length (rotation and deformation scale with it)
  double s;           // size
};

// Writes p_t0 / p_t1 of the points of P into out at point offset `first`.
void place(Rng &rng, const Primitive &P, double tc, Linear_query &out, int first) {
  V3 z{0, 0, 0};
  for (V3 p : P.q) z = z + p;
  z = (1.0 / static_cast<double>(P.q.size())) * z;
  V3 ax = rng.direction();
  double phi = rng.u(0, 0.2) * P.d / P.s;
  for (std::size_t k = 0; k < P.q.size(); ++k) {
    V3 D = P.u + phi * cross(ax, P.q[k] - z) + (0.05 * P.d) * rng.in_ball();
    V3 a = P.q[k] - tc * D, b = P.q[k] + (1 - tc) * D;
    double *p0 = out.t0 + 3 * (first + k), *p1 = out.t1 + 3 * (first + k);
    p0[0] = a.x, p0[1] = a.y, p0[2] = a.z;
    p1[0] = b.x, p1[1] = b.y, p1[2] = b.z;
  }
}

Linear_query make_one(Rng &rng, std::size_t i) {
  Linear_query out;
  out.kind = i % 2 == 0 ? PCCD_VERTEX_FACE : PCCD_EDGE_EDGE;
  Case cs = Case::colliding;
  if (rng.u(0, 1) >= kColliding) cs = static_cast<Case>(1 + std::min(2, static_cast<int>(rng.u(0, 3))));
  V3 c{rng.u(-1, 1), rng.u(-1, 1), rng.u(-1, 1)};
  V3 n = rng.direction();
  V3 r = rng.direction();  // e1: a direction made orthogonal to n (redrawn when nearly parallel)
  while (std::fabs(dot(r, n)) > 0.99) r = rng.direction();
  V3 e1 = unit(r - dot(r, n) * n);
  V3 e2 = cross(n, e1);
  double tc = rng.u(0, 1);
  if (cs == Case::short_) tc = 1;
  Primitive A, B;
  A.s = rng.log_u(1e-2, 1);
  double d_A = rng.log_u(1e-3, 1e-1);
  A.u = d_A * rng.direction();
  double d = rng.log_u(1e-3, 1e-1);
  A.d = B.d = d;  // the non-rigid parts of both scale with the relative displacement
  double al = cs == Case::over ? 90 * kDeg : rng.u(0, 60 * kDeg);
  double ga = rng.u(0, 2 * kPi);
  V3 tau = std::cos(ga) * e1 + std::sin(ga) * e2;
  V3 w = d * (std::cos(al) * (-1.0 * n) + std::sin(al) * tau);
  B.u = A.u + w;
  double g = d * rng.log_u(1e-2, 3);
  if (out.kind == PCCD_VERTEX_FACE) {
    for (int k = 0; k < 3; ++k) {
      double th = 2 * kPi * k / 3 + rng.u(-0.4, 0.4), r = rng.u(0.5, 1);
      A.q.push_back(c + (A.s * r) * (std::cos(th) * e1 + std::sin(th) * e2));
    }
    double x = rng.u(0, 1), y = rng.u(0, 1);  // uniform on the simplex: sorted cuts
    double lo = std::min(x, y), hi = std::max(x, y);
    double b[3] = {lo, hi - lo, 1 - hi};
    V3 P{0, 0, 0};
    for (int k = 0; k < 3; ++k) P = P + (0.1 / 3 + 0.9 * b[k]) * A.q[k];
    V3 v = P;
    if (cs == Case::short_ || cs == Case::over) v = P + g * n;
    if (cs == Case::beside) {
      int k = std::min(2, static_cast<int>(rng.u(0, 3)));
      V3 f = A.q[k], h = A.q[(k + 1) % 3];
      V3 M = f + rng.u(0.05, 0.95) * (h - f);
      V3 o = unit(cross(h - f, n));  // in the plane, perpendicular to the side
      if (dot(o, A.q[(k + 2) % 3] - f) > 0) o = -1.0 * o;  // pointing away from the face
      v = M + g * o;
    }
    B.s = A.s;
    B.q.push_back(v);
    place(rng, B, tc, out, 0);
    place(rng, A, tc, out, 1);
  } else {
    double la = rng.u(0.05, 0.95);
    A.q.push_back(c - (la * A.s) * e1);
    A.q.push_back(c + ((1 - la) * A.s) * e1);
    B.s = rng.log_u(1e-2, 1);
    double be = rng.u(20 * kDeg, 160 * kDeg);
    V3 bd = std::cos(be) * e1 + std::sin(be) * e2;
    double lb = rng.u(0.05, 0.95);
    V3 o{0, 0, 0};
    if (cs == Case::short_ || cs == Case::over) o = g * n;
    if (cs == Case::beside) lb = -g / B.s;
    V3 b0 = c + o - (lb * B.s) * bd;
    B.q.push_back(b0);
    B.q.push_back(b0 + B.s * bd);
    place(rng, A, tc, out, 0);
    place(rng, B, tc, out, 2);
  }
  char label[64];
  std::snprintf(label, sizeof label, "sim #%zu (%s)", i, case_name(cs));
  out.label = label;
  return out;
}

[[noreturn]] void die(const std::string &msg) {
  std::fprintf(stderr, "bench_linear: %s\n", msg.c_str());
  std::exit(2);
}

// A decimal integer string as sign and magnitude; exits when it does not fit 127 bits.
unsigned __int128 parse_magnitude(const std::string &s, bool *negative, const std::string &where) {
  std::size_t i = 0;
  *negative = false;
  if (i < s.size() && (s[i] == '-' || s[i] == '+')) *negative = s[i++] == '-';
  if (i == s.size()) die(where + ": empty number");
  unsigned __int128 v = 0;
  const unsigned __int128 limit = (~static_cast<unsigned __int128>(0)) / 10 - 9;
  for (; i < s.size(); ++i) {
    if (s[i] < '0' || s[i] > '9') die(where + ": '" + s + "' is not an integer");
    if (v > limit) die(where + ": '" + s + "' does not fit 127 bits");
    v = 10 * v + static_cast<unsigned>(s[i] - '0');
  }
  return v;
}

// num / den exactly as a double: den must be a power of two and the odd part of num at
// most 53 bits, and the result normal; exits naming `where` otherwise.
double exact_ratio(const std::string &num_s, const std::string &den_s, const std::string &where) {
  bool neg = false, den_neg = false;
  unsigned __int128 num = parse_magnitude(num_s, &neg, where);
  unsigned __int128 den = parse_magnitude(den_s, &den_neg, where);
  if (den_neg || den == 0 || (den & (den - 1)) != 0)
    die(where + ": denominator " + den_s + " is not a positive power of two");
  int e = 0;
  while ((den >> e) != 1) ++e;
  if (num == 0) return 0.0;
  int k = 0;
  while ((num & 1) == 0) num >>= 1, ++k;
  if (num >> 53) die(where + ": " + num_s + "/" + den_s + " needs more than 53 bits");
  double m = static_cast<double>(static_cast<std::uint64_t>(num));  // exact: < 2^53
  double x = std::ldexp(m, k - e);
  if (!std::isnormal(x) || std::ldexp(x, e - k) != m)
    die(where + ": " + num_s + "/" + den_s + " is not exactly a double");
  return neg ? -x : x;
}

}  // namespace

std::vector<Linear_query> make_sim_queries(std::uint64_t seed, std::size_t n) {
  Rng rng(seed);
  std::vector<Linear_query> out;
  out.reserve(n);
  for (std::size_t i = 0; i < n; ++i) out.push_back(make_one(rng, i));
  return out;
}

std::vector<Linear_query> read_query_csvs(const std::string &root) {
  namespace fs = std::filesystem;
  std::vector<fs::path> files;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(root, ec), end; !ec && it != end; it.increment(ec))
    if (it->is_regular_file() && it->path().extension() == ".csv") files.push_back(it->path());
  if (ec) die(root + ": " + ec.message() + " (set POLYCCD_QUERY_DIR)");
  if (files.empty()) die("no *.csv under " + root + " (set POLYCCD_QUERY_DIR)");
  std::sort(files.begin(), files.end());
  std::vector<Linear_query> out;
  for (const fs::path &f : files) {
    std::string folder = f.parent_path().filename().string();
    if (folder != "vertex-face" && folder != "edge-edge")
      die(f.string() + ": folder name '" + folder + "' is not vertex-face or edge-edge");
    pccd_kind kind = folder == "vertex-face" ? PCCD_VERTEX_FACE : PCCD_EDGE_EDGE;
    std::ifstream in(f);
    std::string line;
    std::size_t row = 0;
    Linear_query q;
    std::string rel = fs::relative(f, root).string();
    while (std::getline(in, line)) {
      if (!line.empty() && line.back() == '\r') line.pop_back();
      if (line.empty()) continue;
      std::vector<std::string> cells;
      std::stringstream ss(line);
      for (std::string cell; std::getline(ss, cell, ',');) cells.push_back(cell);
      std::string where = rel + " row " + std::to_string(row + 1);
      if (cells.size() != 7) die(where + ": " + std::to_string(cells.size()) + " columns, not 7");
      std::size_t r = row % 8;
      double *p = r < 4 ? q.t0 + 3 * r : q.t1 + 3 * (r - 4);
      for (int a = 0; a < 3; ++a)
        p[a] = exact_ratio(cells[2 * a], cells[2 * a + 1], where + " column " + std::to_string(2 * a + 1));
      int truth = cells[6] == "1" ? 1 : cells[6] == "0" ? 0 : -1;
      if (truth < 0 || (r > 0 && truth != q.truth)) die(where + ": bad or inconsistent truth " + cells[6]);
      q.truth = truth;
      if (r == 7) {
        q.kind = kind;
        q.label = rel + " #" + std::to_string(row / 8);
        out.push_back(q);
        q = Linear_query();
      }
      ++row;
    }
    if (row % 8 != 0) die(rel + ": " + std::to_string(row) + " rows, not a multiple of 8");
  }
  return out;
}

}  // namespace bench
