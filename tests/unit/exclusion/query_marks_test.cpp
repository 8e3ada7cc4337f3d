#include "kernels/exclusion/query_marks.h"

#include <gtest/gtest.h>

#include <random>
#include <set>

namespace selfsim::exclusion {
namespace {

// Edge marks against a std::set: each vertex pair once per query, either way round, through the table's
// growth, and forgotten by the next query.
TEST(EdgeMarks, EachEdgeOncePerQueryEitherWayRound) {
  EdgeMarks marks;
  std::mt19937 random(7);
  for (int query = 0; query < 50; ++query) {
    marks.next_query();
    std::set<std::pair<std::uint32_t, std::uint32_t>> seen;
    const int edges = query % 10 == 0 ? 5000 : 40;  // some queries grow the table
    for (int i = 0; i < edges; ++i) {
      const std::uint32_t a = random() % 300, b = random() % 300;
      const bool expected = seen.insert({std::min(a, b), std::max(a, b)}).second;
      ASSERT_EQ(marks.first_visit(a, b), expected) << query << " " << a << " " << b;
      ASSERT_FALSE(marks.first_visit(b, a));
    }
  }
}

}  // namespace
}  // namespace selfsim::exclusion
