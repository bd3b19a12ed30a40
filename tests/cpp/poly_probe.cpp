// Test probe for lib/poly (not part of the library): reads one query per line
//   <a> <b> | f0 f1 ... | g0 g1 ... | g0 g1 ...
// (rational strings, ascending coefficients) and prints
//   <exact count> <interval count or "u"> <taq(g_1, f) exact> <exact count, Hermite only>
// where count = #{t in (a, b) : f(t) = 0, every g_i(t) > 0} by Hermite/Hankel sign
// determination. tests/test_hermite.py compares this with sympy's root isolation.
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "arith/errors.h"
#include "poly/count.h"

using namespace pccd;
using arith::Interval;
using arith::Rational;

static std::vector<std::string> split(const std::string &s, char sep) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, sep)) out.push_back(item);
  return out;
}

static poly::Poly<Rational> parse_poly(const std::string &s) {
  std::stringstream ss(s);
  std::string tok;
  std::vector<Rational> c;
  while (ss >> tok) c.push_back(arith::parse_rational(tok, "probe"));
  return poly::Poly<Rational>(c);
}

int main() {
  std::string line;
  util::Round_to_nearest nearest;  // as a C call runs
  while (std::getline(std::cin, line)) {
    if (line.empty()) continue;
    auto parts = split(line, '|');
    std::stringstream ab(parts[0]);
    std::string sa, sb;
    ab >> sa >> sb;
    Rational a = arith::parse_rational(sa, "a"), b = arith::parse_rational(sb, "b");
    poly::Poly<Rational> f = parse_poly(parts[1]);
    std::vector<poly::Poly<Rational>> g;
    for (size_t i = 2; i < parts.size(); ++i) g.push_back(parse_poly(parts[i]));
    long exact = poly::count_roots(f, g, a, b);
    std::string inter = "u";
    try {
      std::vector<poly::Poly<Interval>> gi;
      for (auto &x : g) gi.push_back(poly::convert<Interval>(x));
      inter = std::to_string(poly::count_roots(poly::convert<Interval>(f), gi, arith::enclose(a),
                                               arith::enclose(b)));
    } catch (const arith::Uncertain &) {
    }
    int taq = 0;
    if (f.degree() >= 1) {
      // The exact Hermite works on integer normal forms (same TaQ): see hermite.h.
      poly::Poly<Rational> F = poly::primitive_monic_sign(f);
      poly::Hermite<Rational> H(F);
      taq = H.taq(g.empty() ? poly::Poly<Rational>::constant(1)
                            : poly::prem_positive(poly::primitive_positive(g[0]), F));
    }
    long hermite_only = poly::count_roots(f, g, a, b, /*filters=*/false);
    std::cout << exact << " " << inter << " " << taq << " " << hermite_only << "\n";
  }
  return 0;
}
