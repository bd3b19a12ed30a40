// Reads the file of tests/ompl/scene_file.py (its docstring has the format) into C API
// handles: the chain, the robot with its bodies and allowed pairs, the obstacles, and
// what bindings/ompl/polyccd_ompl.hpp's Robot_checks takes (dim_links, base, mimic), the
// state space's bounds (the joint limits; [-pi, pi] without) and the queries. For the
// test (test_ompl_validator.cpp) and the benchmark (tests/bench/bench_planning_ompl.cpp).
// Throws std::runtime_error naming the record that is wrong.
#ifndef POLYCCD_TESTS_OMPL_SCENE_FILE_HPP
#define POLYCCD_TESTS_OMPL_SCENE_FILE_HPP

#include <cmath>
#include <fstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "polyccd.h"
#include "polyccd_ompl.hpp"

namespace scene_file {

struct Scene {
  pccd_chain *chain = nullptr;
  pccd_robot *robot = nullptr;
  std::vector<pccd_body *> bodies;     // the robot's (the robot keeps its own references)
  std::vector<pccd_body *> obstacles;
  std::vector<size_t> dim_links;       // state dimension -> chain link
  std::vector<double> base;            // chain values of the fixed joints
  std::vector<polyccd_ompl::Mimic> mimic;
  std::vector<std::pair<double, double>> bounds;  // per state dimension
  std::vector<std::pair<std::vector<double>, std::vector<double>>> queries;
  std::vector<std::string> dim_names;

  Scene() = default;
  Scene(const Scene &) = delete;
  Scene &operator=(const Scene &) = delete;
  ~Scene() {
    for (pccd_body *b : bodies) pccd_body_free(b);
    for (pccd_body *b : obstacles) pccd_body_free(b);
    pccd_robot_free(robot);
    pccd_chain_free(chain);
  }
  std::vector<const pccd_body *> obstacle_list() const {
    return std::vector<const pccd_body *>(obstacles.begin(), obstacles.end());
  }
};

inline void need(bool ok, const std::string &what) {
  if (!ok) throw std::runtime_error("scene_file: " + what);
}
inline void c_ok(int rc, const std::string &what) {
  if (rc != PCCD_OK) throw std::runtime_error("scene_file: " + what + ": " + pccd_last_error());
}
inline void word(std::istream &in, const char *expected) {
  std::string w;
  in >> w;
  need(bool(in) && w == expected, std::string("expected \"") + expected + "\", got \"" + w + "\"");
}
inline double number(std::istream &in, const std::string &where) {
  std::string w;
  in >> w;
  need(bool(in), where + ": missing number");
  return std::stod(w);  // "inf", "-inf" and repr's digits (which read back exactly)
}

// One "mesh link group solid nv nt d|s" record and its lines; *link, *group: its fields.
inline pccd_body *mesh(std::istream &in, size_t *link, size_t *group, const std::string &where) {
  int solid = 0;
  size_t nv = 0, nt = 0;
  std::string kind;
  word(in, "mesh");
  in >> *link >> *group >> solid >> nv >> nt >> kind;
  need(bool(in) && (kind == "d" || kind == "s"), where + ": bad mesh record");
  std::vector<unsigned> tris(3 * nt);
  pccd_body *b = nullptr;
  std::vector<double> vd;
  std::vector<std::string> vs;
  for (size_t i = 0; i < 3 * nv; ++i) {
    std::string w;
    in >> w;
    kind == "d" ? vd.push_back(std::stod(w)) : vs.push_back(w);
  }
  for (auto &t : tris) in >> t;
  need(bool(in), where + ": truncated");
  if (kind == "d") {
    c_ok(pccd_body_new_mesh_d(&b, vd.data(), nv, tris.data(), nt), where);
  } else {
    std::vector<const char *> p;
    for (auto &s : vs) p.push_back(s.c_str());
    c_ok(pccd_body_new_mesh_s(&b, p.data(), nv, tris.data(), nt), where);
  }
  if (solid) {
    pccd_body *s = nullptr;
    int rc = pccd_body_new_solid(&s, b);
    pccd_body_free(b);
    c_ok(rc, where + " (solid)");
    b = s;
  }
  return b;
}

inline void read(const std::string &path, Scene &sc) {
  std::ifstream in(path);
  need(bool(in), path + ": cannot open");
  word(in, "polyccd-ompl-scene");
  word(in, "1");
  size_t n = 0;
  word(in, "links");
  in >> n;
  c_ok(pccd_chain_new(&sc.chain), "chain");
  std::vector<int> kinds;
  for (size_t k = 0; k < n; ++k) {
    long parent = 0;
    std::string joint, a[3];
    double xyz[3], rpy[3], axis[3] = {0, 0, 0};
    in >> parent >> joint >> a[0] >> a[1] >> a[2];
    for (auto &x : xyz) x = number(in, "links");
    for (auto &x : rpy) x = number(in, "links");
    int type = joint == "fixed" ? PCCD_JOINT_FIXED : joint == "revolute" ? PCCD_JOINT_REVOLUTE
             : joint == "continuous" ? PCCD_JOINT_CONTINUOUS : joint == "prismatic" ? PCCD_JOINT_PRISMATIC : -1;
    need(bool(in) && type >= 0, "links[" + std::to_string(k) + "]: bad record");
    if (type != PCCD_JOINT_FIXED)
      for (int i = 0; i < 3; ++i) axis[i] = std::stod(a[i]);
    c_ok(pccd_chain_add_link(sc.chain, parent, type, type == PCCD_JOINT_FIXED ? nullptr : axis, xyz,
                             rpy, nullptr),
         "links[" + std::to_string(k) + "]");
    kinds.push_back(type);
  }
  word(in, "joints");
  size_t nj = 0;
  in >> nj;
  std::vector<std::string> names(nj);
  std::vector<size_t> column(nj);
  std::vector<std::pair<double, double>> limits(nj);
  for (size_t j = 0; j < nj; ++j) {
    in >> names[j] >> column[j];
    limits[j].first = number(in, "joints");
    limits[j].second = number(in, "joints");
    need(bool(in) && column[j] < n, "joints[" + std::to_string(j) + "]: bad record");
  }
  word(in, "mimic");
  size_t nm = 0;
  in >> nm;
  std::vector<std::pair<size_t, size_t>> mimic_of(nm);  // (chain link, leader joint)
  std::vector<std::pair<double, double>> mimic_ab(nm);
  for (size_t i = 0; i < nm; ++i) {
    in >> mimic_of[i].first >> mimic_of[i].second;
    mimic_ab[i].first = number(in, "mimic");
    mimic_ab[i].second = number(in, "mimic");
    need(bool(in) && mimic_of[i].first < n && mimic_of[i].second < nj, "mimic: bad record");
  }
  c_ok(pccd_robot_new(&sc.robot, sc.chain), "robot");
  word(in, "bodies");
  in >> n;
  for (size_t i = 0; i < n; ++i) {
    size_t link = 0, group = 0;
    std::string where = "bodies[" + std::to_string(i) + "]";
    sc.bodies.push_back(mesh(in, &link, &group, where));
    c_ok(pccd_robot_add_body(sc.robot, link, group, sc.bodies.back(), nullptr), where);
  }
  word(in, "allowed");
  in >> n;
  std::vector<size_t> pairs(2 * n);
  for (auto &g : pairs) in >> g;
  need(bool(in), "allowed: truncated");
  c_ok(pccd_robot_set_allowed(sc.robot, pairs.data(), n), "allowed");
  word(in, "obstacles");
  in >> n;
  for (size_t i = 0; i < n; ++i) {
    size_t link = 0, group = 0;
    sc.obstacles.push_back(mesh(in, &link, &group, "obstacles[" + std::to_string(i) + "]"));
  }
  word(in, "planned");
  size_t d = 0;
  in >> d;
  std::vector<size_t> planned(d);
  for (auto &j : planned) in >> j;
  word(in, "fixed");
  std::vector<double> value(nj);
  for (auto &x : value) x = number(in, "fixed");
  size_t links = 0;
  pccd_chain_size(sc.chain, &links);
  sc.base.assign(links, 0.0);
  for (size_t j = 0; j < nj; ++j) sc.base[column[j]] = value[j];
  std::vector<long> dim_of_joint(nj, -1);
  for (size_t i = 0; i < d; ++i) {
    need(planned[i] < nj, "planned: bad joint index");
    dim_of_joint[planned[i]] = long(i);
    sc.dim_links.push_back(column[planned[i]]);
    sc.dim_names.push_back(names[planned[i]]);
    bool turns = kinds[column[planned[i]]] == PCCD_JOINT_REVOLUTE ||
                 kinds[column[planned[i]]] == PCCD_JOINT_CONTINUOUS;
    auto lim = limits[planned[i]];
    if (!std::isfinite(lim.first) || !std::isfinite(lim.second))
      lim = turns ? std::make_pair(-M_PI, M_PI) : lim;
    need(std::isfinite(lim.first) && std::isfinite(lim.second), "planned: an unbounded joint");
    sc.bounds.push_back(lim);
  }
  for (size_t i = 0; i < nm; ++i) {  // a mimic of a fixed joint: a fixed value
    auto [link, leader] = mimic_of[i];
    if (dim_of_joint[leader] < 0)
      sc.base[link] = mimic_ab[i].first * value[leader] + mimic_ab[i].second;
    else
      sc.mimic.push_back({link, size_t(dim_of_joint[leader]), mimic_ab[i].first, mimic_ab[i].second});
  }
  word(in, "queries");
  in >> n;
  for (size_t q = 0; q < n; ++q) {
    std::vector<double> a(d), b(d);
    for (auto &x : a) x = number(in, "queries");
    for (auto &x : b) x = number(in, "queries");
    sc.queries.emplace_back(a, b);
  }
}

}  // namespace scene_file

#endif
