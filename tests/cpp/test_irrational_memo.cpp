// narrow::Query_irrational (lib/narrow/irrational_memo.h): the features of different
// queries of one body pair are the same memo entry exactly when they hold the same
// points of the two bodies. A vertex-vertex feature of a vertex-face query and of an
// edge-edge query on the same two points share an entry, and so do vertex-edge features
// with the edge's ends in either order; a feature with any other point, the same
// indices on the other side, or a face or edge-edge feature never matches. The memo
// answers only for the delta it was bound to.
#include "narrow/irrational_memo.h"

#include "expect.h"

using pccd::narrow::Irrational_memo;
using pccd::narrow::Query_irrational;
using pccd::pred::Feature;
namespace pred = pccd::pred;

namespace {

// A vertex-face query: A's vertex 7 against B's triangle (3, 5, 9). An edge-edge query:
// A's edge (7, 8) against B's edge (9, 3). (Pair_ctx::query_points's orders.)
const Query_irrational::Points kVF{{{0, 7}, {1, 3}, {1, 5}, {1, 9}}};
const Query_irrational::Points kEE{{{0, 7}, {0, 8}, {1, 9}, {1, 3}}};
// The same points with the sides swapped (an FV query: B's vertex 7, A's triangle).
const Query_irrational::Points kFV{{{1, 7}, {0, 3}, {0, 5}, {0, 9}}};

Feature vv(int a, int b) { return Feature{pred::VERTEX_VERTEX, {{a, b, -1, -1}}}; }
Feature ve(int c, int e0, int e1) { return Feature{pred::VERTEX_EDGE, {{c, e0, e1, -1}}}; }

}  // namespace

int main() {
  {
    Irrational_memo memo;
    expect(memo.bind(pccd::arith::Rational(1, 20)), "binds to its first delta");
    Query_irrational vf(memo, kVF, 4), ee(memo, kEE, 4), fv(memo, kFV, 4);
    expect(!vf.has(vv(0, 3)), "empty memo");
    vf.add(vv(0, 3));  // A7 - B9
    expect(vf.has(vv(0, 3)), "the feature added");
    expect(ee.has(vv(0, 2)) && ee.has(vv(2, 0)), "A7 - B9 of the edge-edge query, either order");
    expect(!ee.has(vv(0, 3)), "A7 - B3: another point");
    expect(!ee.has(vv(1, 2)), "A8 - B9: another point");
    expect(!vf.has(vv(0, 1)) && !vf.has(vv(0, 2)), "A7 - B3, A7 - B5");
    expect(!fv.has(vv(0, 3)), "B7 - A9: the same indices on the other sides");
    expect(!vf.has(ve(0, 1, 3)), "a vertex-edge feature is not its vertex-vertex one");

    ee.add(ve(0, 2, 3));  // A7 - B edge (9, 3)
    expect(vf.has(ve(0, 3, 1)) && vf.has(ve(0, 1, 3)), "A7 - B edge (3, 9), either end first");
    expect(!vf.has(ve(0, 1, 2)), "A7 - B edge (3, 5)");
    expect(!ee.has(ve(1, 2, 3)), "A8 - B edge (9, 3)");
    expect(!fv.has(ve(0, 1, 3)), "B7 - A edge (3, 9)");
    expect(!ee.has(ve(2, 0, 1)), "B9 - A edge (7, 8): not added");

    const Feature face{pred::VERTEX_FACE, {{0, 1, 2, 3}}}, edges{pred::EDGE_EDGE, {{0, 1, 2, 3}}};
    vf.add(face);
    ee.add(edges);
    expect(!vf.has(face) && !ee.has(edges), "face and edge-edge features are not kept");
    const Feature bad{pred::VERTEX_VERTEX, {{0, 4, -1, -1}}}, same_side{pred::VERTEX_VERTEX, {{0, 1, -1, -1}}};
    vf.add(bad);
    ee.add(same_side);  // A7, A8: not a feature of two bodies
    expect(!vf.has(bad) && !ee.has(same_side), "points out of range or on one side");
    Query_irrational two(memo, kVF, 2);  // a query of two points: index 3 is outside
    expect(!two.has(vv(0, 3)), "an index past the query's points");

    expect(memo.bind(pccd::arith::Rational(1, 20)), "the same delta");
    expect(!memo.bind(pccd::arith::Rational(1, 21)), "another delta is refused");
  }
  std::printf("%ld passed, %ld failed\n", passed, failed);
  return failed != 0;
}
