// Bowyer's own rule (issue 21): his published results to every printed digit, the grid against his brute
// force bit for bit, and the curve's invariants.
#include "kernels/exclusion/original_rule.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "kernels/base/error.h"

namespace selfsim::exclusion {
namespace {

// His square boundary as his program reads it (clockwise from the origin) and Figure 3's start.
Region his_square() { return Region({{{0, 0}, {0, 1}, {1, 1}, {1, 0}}}); }
Polyline diagonal() { return Polyline::single({{0, 0}, {1, 1}}); }

CurveResult grow(const Region& region, const Polyline& start, double factor, int levels, Scan scan = Scan::alternate,
                 bool brute_force = false, double radius = 0.1) {
  CurveOptions o;
  o.radius = radius;
  o.factor = factor;
  o.levels = levels;
  o.scan = scan;
  o.brute_force = brute_force;
  return original_curve(region, start, o, no_progress());
}

// A row of his results files for the first curve at level n (its points of level ≤ n, in order):
// segments, total length, sum of squared lengths, longest, shortest; summed in chain order and printed
// as his C++ stream prints doubles (6 significant digits).
struct Row {
  int count = 0;
  double sum = 0, sum2 = 0, longest = 0, shortest = 1e100;
  std::string text() const {
    char s[160];
    std::snprintf(s, sizeof s, "%d,%g,%g,%g,%g", count, sum, sum2, longest, shortest);
    return s;
  }
};

Row row(const Polyline& c, int n) {
  const Field* level = c.point_fields.find("level");
  Row r;
  bool first = true;
  Vec2 previous;
  for (std::size_t k = 0; k < c.path(0).size(); ++k) {
    if (level->at(k) > n) continue;
    const Vec2 p = c.path(0)[k];
    if (!first) {
      const double dx = previous.x - p.x, dy = previous.y - p.y, q = dx * dx + dy * dy, s = std::sqrt(q);
      r.sum2 += q;
      r.longest = std::max(r.longest, s);
      r.shortest = std::min(r.shortest, s);
      r.sum += s;
      ++r.count;
    }
    previous = p;
    first = false;
  }
  return r;
}

void expect_rows(const CurveResult& r, const std::vector<std::string>& rows, const std::string& what) {
  for (std::size_t n = 0; n < rows.size(); ++n)
    EXPECT_EQ(row(r.curve, static_cast<int>(n)).text(), rows[n]) << what << ", level " << n;
}

void expect_same_points(const CurveResult& a, const CurveResult& b, const std::string& what) {
  ASSERT_EQ(a.curve.points.size(), b.curve.points.size()) << what;
  for (std::size_t k = 0; k < a.curve.points.size(); ++k) {
    // Bit for bit: == on doubles, and no NaN anywhere.
    ASSERT_EQ(a.curve.points[k].x, b.curve.points[k].x) << what << ", point " << k;
    ASSERT_EQ(a.curve.points[k].y, b.curve.points[k].y) << what << ", point " << k;
  }
  ASSERT_EQ(a.levels.size(), b.levels.size()) << what;
  for (std::size_t l = 0; l < a.levels.size(); ++l) EXPECT_EQ(a.levels[l].stuck, b.levels[l].stuck) << what;
}

}  // namespace

// The table: the paper's lengths for Figure 3's conditions (unit square, the diagonal, radius 0.1,
// factor 0.8), levels 0 to 14, from one run.
TEST(OriginalRule, Figure3LengthsMatchBowyersTable) {
  const double published[] = {1.41421, 1.81108, 3.0314,  3.88056, 5.62506, 7.42846, 9.90736, 14.3601,
                              18.7554, 25.7971, 35.0811, 47.5111, 64.168,  85.7657, 114.233};
  const CurveResult r = grow(his_square(), diagonal(), 0.8, 14);
  for (int n = 0; n <= 14; ++n) {
    const double length = row(r.curve, n).sum;
    EXPECT_NEAR(length / published[n], 1, 5e-6) << "level " << n << ": " << length;
  }
}

// Every column of his results file t-8.txt (factor 0.8), levels 0 to 15, to every printed digit, and the
// stuck splits per level that an independent re-computation of his program counted.
TEST(OriginalRule, Figure3RowsMatchHisResultsFile) {
  const std::vector<std::string> t8 = {"1,1.41421,2,1.41421,1.41421",
                                       "2,1.81108,1.64,0.905539,0.905539",
                                       "4,3.0314,2.50467,0.985517,0.530181",
                                       "8,3.88056,2.13344,0.765021,0.311406",
                                       "16,5.62506,2.22583,0.642465,0.192983",
                                       "32,7.42846,2.255,0.661943,0.106217",
                                       "64,9.90736,2.18831,0.574032,0.0568176",
                                       "128,14.3601,2.50384,0.489897,0.030379",
                                       "256,18.7554,2.16155,0.41931,0.0175171",
                                       "512,25.7971,2.1124,0.384648,0.00924854",
                                       "1024,35.0811,1.93088,0.240101,0.00462427",
                                       "2048,47.5111,1.84924,0.194749,0.00231213",
                                       "4096,64.168,1.78002,0.182775,0.00115607",
                                       "8192,85.7657,1.69317,0.170426,0.000578034",
                                       "16384,114.233,1.56672,0.155946,0.000289017",
                                       "32768,151.328,1.43903,0.143045,0.000144508"};
  const CurveResult r = grow(his_square(), diagonal(), 0.8, 15);
  expect_rows(r, t8, "factor 0.8");
  const std::size_t stuck[] = {0, 0, 0, 0, 2, 2, 0, 5, 9, 37, 93};
  for (int l = 0; l < 11; ++l) EXPECT_EQ(r.levels[l].stuck, stuck[l]) << "level " << l + 1;
  // The first split ties exactly and goes to the left of the diagonal, toward the top-left corner.
  const Vec2 first = r.curve.points[r.curve.points.size() / 2];
  EXPECT_NEAR(first.x, 0.1, 1e-12);
  EXPECT_NEAR(first.y, 0.9, 1e-12);
}

// His other results files (Figure 8's factors), levels 0 to 12: beyond that the smallest factors' radii
// reach rounding and his 2004 build's extended precision shows (t-3 from level 13).
TEST(OriginalRule, OtherFactorsMatchTheirResultsFiles) {
  struct Table {
    double factor;
    std::vector<std::string> rows;
  };
  const std::vector<Table> tables = {
      {0.3,
       {"1,1.41421,2,1.41421,1.41421", "2,1.81108,1.64,0.905539,0.905539", "4,3.17543,2.74476,1.03046,0.557254",
        "8,4.32031,2.58457,0.827776,0.381673", "16,6.29427,2.85922,0.718052,0.203264",
        "32,9.05383,3.1386,0.642932,0.101775", "64,13.0168,3.28348,0.583519,0.0509837",
        "128,18.3589,3.55522,0.531777,0.0275368", "256,25.6476,3.6353,0.485107,0.0149349",
        "512,35.9539,3.6773,0.442722,0.00842531", "1024,50.4938,3.81656,0.404098,0.00480142",
        "2048,70.2653,3.90106,0.36886,0.00260628", "4096,97.9544,3.95083,0.336701,0.00130315"}},
      {0.5,
       {"1,1.41421,2,1.41421,1.41421", "2,1.81108,1.64,0.905539,0.905539", "4,3.11702,2.64642,1.01242,0.546087",
        "8,4.18072,2.44027,0.810738,0.355547", "16,6.21738,2.76923,0.723669,0.250571",
        "32,8.77943,3.05715,0.732413,0.14977", "64,12.6936,3.37456,0.710195,0.0780406",
        "128,18.0047,3.73321,0.703261,0.0390741", "256,24.9174,3.94852,0.695816,0.0196904",
        "512,34.8621,4.20745,0.690054,0.0101624", "1024,48.657,4.45335,0.684394,0.00636153",
        "2048,66.8795,4.5551,0.67897,0.00427325", "4096,91.3187,4.63985,0.673783,0.00242562"}},
      {0.6,
       {"1,1.41421,2,1.41421,1.41421", "2,1.81108,1.64,0.905539,0.905539", "4,3.08821,2.5984,1.00343,0.540669",
        "8,4.09215,2.34884,0.798254,0.341214", "16,6.01002,2.57652,0.709355,0.229699",
        "32,8.47403,2.93236,0.741856,0.141636", "64,12.3076,3.21545,0.671311,0.0777192",
        "128,17.1984,3.32727,0.627961,0.0389839", "256,24.149,3.59676,0.589761,0.0198094",
        "512,34.4687,3.86575,0.563182,0.0104142", "1024,48.2938,4.04715,0.543136,0.00582331",
        "2048,66.7769,4.18514,0.526836,0.00394953", "4096,92.1114,4.30597,0.512774,0.00197477"}},
      {0.7,
       {"1,1.41421,2,1.41421,1.41421", "2,1.81108,1.64,0.905539,0.905539", "4,3.05966,2.55115,0.994465,0.535366",
        "8,3.99177,2.24604,0.783032,0.326384", "16,5.85392,2.42201,0.682069,0.208297",
        "32,8.01547,2.61618,0.709247,0.121888", "64,11.2132,2.73613,0.63352,0.078903",
        "128,16.4093,3.18808,0.595521,0.0423276", "256,22.358,3.13348,0.557612,0.0240016",
        "512,31.1485,3.20594,0.534467,0.0139373", "1024,44.2608,3.39613,0.515463,0.008031",
        "2048,61.1387,3.3794,0.504244,0.00419873", "4096,86.0396,3.50782,0.492996,0.00226395"}},
      {0.9,
       {"1,1.41421,2,1.41421,1.41421", "2,1.81108,1.64,0.905539,0.905539", "4,3.00342,2.45896,0.976591,0.525118",
        "8,3.76,2.01311,0.744189,0.296719", "16,4.99167,1.79725,0.592795,0.183247",
        "32,6.51504,1.78588,0.597761,0.092854", "64,8.28446,1.50234,0.396812,0.046427",
        "128,10.583,1.26236,0.276408,0.0232135", "256,13.2649,1.02425,0.207338,0.0116068",
        "512,17.5234,0.960018,0.194982,0.00580338", "1024,21.282,0.704417,0.132687,0.00290169",
        "2048,26.4133,0.579269,0.120219,0.00145084", "4096,31.8496,0.437897,0.0680814,0.000725422"}},
      {0.95,
       {"1,1.41421,2,1.41421,1.41421", "2,1.81108,1.64,0.905539,0.905539", "4,2.98954,2.43639,0.972137,0.522634",
        "8,3.69687,1.95082,0.732716,0.289653", "16,4.72514,1.63066,0.565236,0.175321",
        "32,6.11529,1.57429,0.558618,0.0888582", "64,7.4912,1.33572,0.462222,0.0444291",
        "128,9.20474,1.01842,0.256854,0.0222146", "256,10.9696,0.703688,0.161944,0.0111073",
        "512,12.9826,0.486972,0.0963289,0.00555364", "1024,15.2354,0.352981,0.0662426,0.00277682",
        "2048,17.3706,0.24608,0.063137,0.00138841", "4096,19.9764,0.178353,0.0432683,0.000694205"}}};
  for (const Table& t : tables)
    expect_rows(grow(his_square(), diagonal(), t.factor, 12), t.rows, "factor " + std::to_string(t.factor));
}

// `forward` is his program without alternation (zag = 0): it departs from t-8 at level 3.
TEST(OriginalRule, ForwardScanIsHisProgramWithoutAlternation) {
  const CurveResult r = grow(his_square(), diagonal(), 0.8, 3, Scan::forward);
  EXPECT_EQ(row(r.curve, 2).text(), "4,3.0314,2.50467,0.985517,0.530181");
  EXPECT_NEAR(row(r.curve, 3).sum, 3.85165, 5e-6);
}

TEST(OriginalRule, GridMatchesBruteForceBitForBit) {
  for (const Scan scan : {Scan::alternate, Scan::forward}) {
    const std::string what = scan == Scan::alternate ? "alternate" : "forward";
    expect_same_points(grow(his_square(), diagonal(), 0.8, 10, scan),
                       grow(his_square(), diagonal(), 0.8, 10, scan, true), "Figure 3, " + what);
    // A radius of many segment lengths (vertices far along the bisector matter) and a radius that falls to
    // rounding (crossings whose computed side is noise).
    expect_same_points(grow(his_square(), diagonal(), 0.95, 9, scan),
                       grow(his_square(), diagonal(), 0.95, 9, scan, true), "factor 0.95, " + what);
    expect_same_points(grow(his_square(), diagonal(), 0.3, 11, scan),
                       grow(his_square(), diagonal(), 0.3, 11, scan, true), "factor 0.3, " + what);
  }
}

namespace {

// An L-shaped region with a square hole, a closed start (a triangle) and an open one.
Region l_shape() {
  return Region({{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}, {{1.3, 0.3}, {1.3, 0.6}, {1.6, 0.6}, {1.6, 0.3}}});
}

Polyline two_starts() {
  Polyline start;
  for (Vec2 p : {Vec2{0.2, 1.2}, Vec2{0.8, 1.2}, Vec2{0.5, 1.8}, Vec2{0.2, 1.2}}) start.points.push_back(p);
  start.close_path();
  for (Vec2 p : {Vec2{0.2, 0.2}, Vec2{0.8, 0.8}, Vec2{1.8, 0.8}}) start.points.push_back(p);
  start.close_path();
  return start;
}

}  // namespace

TEST(OriginalRule, SeveralCurvesDoubleKeepTheirStartsAndStayClosed) {
  const Polyline start = two_starts();
  for (const Scan scan : {Scan::alternate, Scan::forward}) {
    const CurveResult r = grow(l_shape(), start, 0.8, 6, scan, false, 0.05);
    expect_same_points(r, grow(l_shape(), start, 0.8, 6, scan, true, 0.05), "L with a hole");
    ASSERT_EQ(r.curve.paths(), 2u);
    EXPECT_EQ(r.curve.path(0).size(), 3u * 64 + 1);
    EXPECT_EQ(r.curve.path(1).size(), 2u * 64 + 1);
    EXPECT_EQ(r.curve.path(0).front(), r.curve.path(0).back());  // closed stays closed
    EXPECT_NE(r.curve.path(1).front(), r.curve.path(1).back());
    ASSERT_EQ(r.levels.size(), 6u);
    for (int l = 0; l < 6; ++l) EXPECT_EQ(r.levels[l].splits, 5u << l) << "level " << l + 1;
    // Start points exactly as given, at level 0; every other point made at a level from 1 to 6.
    const Field* level = r.curve.point_fields.find("level");
    ASSERT_NE(level, nullptr);
    for (std::size_t i = 0; i < 2; ++i) {
      const auto given = start.path(i);
      std::size_t k = 0;
      for (std::size_t j = r.curve.path_begin(i); j < r.curve.path_ends[i]; ++j) {
        const auto l = level->at(j);
        if (l == 0) {
          ASSERT_LT(k, given.size());
          EXPECT_EQ(r.curve.points[j], given[k++]);
        } else {
          EXPECT_GE(l, 1);
          EXPECT_LE(l, 6);
        }
      }
      EXPECT_EQ(k, given.size());
    }
    const Field* curve = r.curve.cell_fields.find("curve");
    ASSERT_NE(curve, nullptr);
    EXPECT_EQ(curve->at(0), 1);
    EXPECT_EQ(curve->at(1), 2);
  }
}

// His program multiplies the radius by the factor after each curve of a level, not once a level. The
// diagonal's first split, stopped by the square's top-left corner at the radius, lands at (r, 1 − r):
// (0.1, 0.9) when it is the first curve, (0.08, 0.92) when a short curve below it splits first.
TEST(OriginalRule, RadiusShrinksAfterEachCurve) {
  Polyline first_diagonal = diagonal();
  for (Vec2 p : {Vec2{0.7, 0.2}, Vec2{0.8, 0.2}}) first_diagonal.points.push_back(p);
  first_diagonal.close_path();
  Polyline diagonal_second = Polyline::single({{0.7, 0.2}, {0.8, 0.2}});
  for (Vec2 p : {Vec2{0, 0}, Vec2{1, 1}}) diagonal_second.points.push_back(p);
  diagonal_second.close_path();
  const CurveResult a = grow(his_square(), first_diagonal, 0.8, 1);
  const CurveResult b = grow(his_square(), diagonal_second, 0.8, 1);
  const Vec2 pa = a.curve.path(0)[1], pb = b.curve.path(1)[1];
  EXPECT_NEAR(pa.x, 0.1, 1e-12);
  EXPECT_NEAR(pa.y, 0.9, 1e-12);
  EXPECT_NEAR(pb.x, 0.08, 1e-12);
  EXPECT_NEAR(pb.y, 0.92, 1e-12);
}

TEST(OriginalRule, LevelZeroIsTheStart) {
  const CurveResult r = grow(his_square(), diagonal(), 0.8, 0);
  ASSERT_EQ(r.curve.points.size(), 2u);
  EXPECT_EQ(r.curve.points[0], (Vec2{0, 0}));
  EXPECT_EQ(r.curve.points[1], (Vec2{1, 1}));
  EXPECT_TRUE(r.levels.empty());
}

TEST(OriginalRule, ScalingByAPowerOfTwoScalesEveryPointExactly) {
  const CurveResult unit = grow(his_square(), diagonal(), 0.8, 8);
  const Region big({{{0, 0}, {0, 8}, {8, 8}, {8, 0}}});
  const CurveResult scaled = grow(big, Polyline::single({{0, 0}, {8, 8}}), 0.8, 8, Scan::alternate, false, 0.8);
  ASSERT_EQ(unit.curve.points.size(), scaled.curve.points.size());
  for (std::size_t k = 0; k < unit.curve.points.size(); ++k)
    ASSERT_EQ(8 * unit.curve.points[k], scaled.curve.points[k]) << "point " << k;
}

TEST(OriginalRule, RefusesWhatItCannotDo) {
  auto error_of = [](CurveOptions o, const Polyline& start) -> std::string {
    try {
      original_curve(his_square(), start, o, no_progress());
    } catch (const Error& e) {
      return e.what();
    }
    return "";
  };
  CurveOptions o;
  o.order = Order::depth;
  EXPECT_NE(error_of(o, diagonal()).find("'order'"), std::string::npos);
  o = CurveOptions{};
  o.radius = 1e-3;
  o.factor = 0.1;
  o.levels = 12;  // 1e-14 at the last level
  EXPECT_NE(error_of(o, diagonal()).find("'radius'"), std::string::npos);
  o = CurveOptions{};
  o.levels = 30;
  o.budget.limit = 1e6;
  EXPECT_NE(error_of(o, diagonal()).find("--max-points"), std::string::npos);
  EXPECT_NE(error_of(CurveOptions{}, Polyline::single({{2, 2}, {3, 3}})).find("outside the region"), std::string::npos);
}

TEST(OriginalRule, StopsWhenCancelled) {
  struct Cancel : Progress {
    int steps = 0;
    bool cancelled() override { return ++steps > 3; }
  } cancel;
  CurveOptions o;
  o.levels = 14;
  EXPECT_THROW(original_curve(his_square(), diagonal(), o, cancel), Cancelled);
}

}  // namespace selfsim::exclusion
