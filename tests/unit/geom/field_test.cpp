#include "kernels/geom/field.h"

#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "kernels/base/error.h"

using namespace selfsim;

namespace {

// The message f.check(count, element) throws; empty when it passes.
std::string check_error(const Fields& f, std::size_t count, const char* element = "point") {
  try {
    f.check(count, element);
  } catch (const Error& e) {
    return e.what();
  }
  return {};
}

Fields one(Field f) {
  Fields fs;
  fs.set(std::move(f));
  return fs;
}

}  // namespace

TEST(Field, IntField) {
  const Field f = int_field("curve", {4, 5, 6});
  EXPECT_EQ(f.name, "curve");
  EXPECT_EQ(f.components, 1);
  EXPECT_EQ(f.scalar(), Scalar::Int32);
  EXPECT_FALSE(f.uniform);
  EXPECT_EQ(f.stored(), 3u);
  ASSERT_EQ(f.ints().size(), 3u);
  EXPECT_EQ(f.ints()[2], 6);
  EXPECT_EQ(f.at(0), 4);
  EXPECT_EQ(f.at(2), 6);
}

TEST(Field, RealFieldWithComponents) {
  const Field f = real_field("color", {0.1, 0.2, 0.3, 1.1, 1.2, 1.3}, 3);
  EXPECT_EQ(f.scalar(), Scalar::Float64);
  EXPECT_EQ(f.components, 3);
  EXPECT_EQ(f.stored(), 2u);
  EXPECT_EQ(f.reals().size(), 6u);
  EXPECT_EQ(f.at(0, 0), 0.1);
  EXPECT_EQ(f.at(0, 2), 0.3);
  EXPECT_EQ(f.at(1, 0), 1.1);
  EXPECT_EQ(f.at(1, 1), 1.2);
  EXPECT_EQ(f.at(1, 2), 1.3);
}

TEST(Field, UniformIntStoresOneTupleForEveryElement) {
  const Field f = uniform_int("level", 7);
  EXPECT_TRUE(f.uniform);
  EXPECT_EQ(f.scalar(), Scalar::Int32);
  EXPECT_EQ(f.components, 1);
  EXPECT_EQ(f.stored(), 1u);
  EXPECT_EQ(f.at(0), 7);
  EXPECT_EQ(f.at(1000000), 7);  // any element reads the one tuple
}

TEST(Field, BytesGrowWithValues) {
  const Field small = real_field("x", std::vector<double>(10, 1.0));
  const Field big = real_field("x", std::vector<double>(1000, 1.0));
  EXPECT_GE(small.bytes(), 10 * sizeof(double));
  EXPECT_GE(big.bytes(), 1000 * sizeof(double));
  EXPECT_GT(big.bytes(), small.bytes());
}

TEST(Fields, SetAppendsInOrderAndReplacesByName) {
  Fields fs;
  EXPECT_TRUE(fs.empty());
  fs.set(uniform_int("level", 1));
  fs.set(real_field("arclength", {0, 1}));
  fs.set(int_field("curve", {3, 4}));
  ASSERT_EQ(fs.list.size(), 3u);
  fs.set(uniform_int("arclength", 9));  // replaced where it was
  ASSERT_EQ(fs.list.size(), 3u);
  EXPECT_EQ(fs.list[0].name, "level");
  EXPECT_EQ(fs.list[1].name, "arclength");
  EXPECT_EQ(fs.list[2].name, "curve");
  EXPECT_TRUE(fs.list[1].uniform);
  EXPECT_EQ(fs.list[1].scalar(), Scalar::Int32);
  EXPECT_EQ(fs.list[1].at(0), 9);
  ASSERT_NE(fs.find("curve"), nullptr);
  EXPECT_EQ(fs.find("curve")->at(1), 4);
  EXPECT_EQ(fs.find("missing"), nullptr);
  EXPECT_FALSE(fs.empty());
}

TEST(Fields, BytesSumsTheFields) {
  Fields fs;
  fs.set(real_field("a", std::vector<double>(100, 0.0)));
  const std::size_t one_field = fs.bytes();
  fs.set(real_field("b", std::vector<double>(100, 0.0)));
  EXPECT_GE(fs.bytes(), 2 * 100 * sizeof(double));
  EXPECT_GT(fs.bytes(), one_field);
}

TEST(FieldsCheck, PassesForGoodFields) {
  Fields fs;
  fs.set(uniform_int("level", 3));
  fs.set(int_field("curve", {1, 2, 3}));
  fs.set(real_field("color", {0, 0, 0, 1, 1, 1, 2, 2, 2}, 3));
  fs.set(real_field("uv", {0, 0, 1, 1, 2, 2}, 2));
  fs.set(real_field(std::string(64, 'a'), {1, 2, 3}));  // 64 characters: the longest allowed
  fs.set(real_field("Mixed_Case_09", {1, 2, 3}));
  EXPECT_EQ(check_error(fs, 3), "");
  EXPECT_EQ(check_error(Fields{}, 0), "");
}

TEST(FieldsCheck, WrongSizeIsNamed) {
  EXPECT_EQ(check_error(one(int_field("curve", {1, 2})), 3, "cell"), "cell field 'curve' has 2 values, expected 3 × 1");
  EXPECT_EQ(check_error(one(real_field("color", {0, 0, 0, 1, 1, 1}, 3)), 3),
            "point field 'color' has 6 values, expected 3 × 3");
  // Too many is as wrong as too few.
  EXPECT_NE(check_error(one(int_field("curve", {1, 2, 3, 4})), 3), "");
}

TEST(FieldsCheck, UniformFieldsNeedExactlyOneTuple) {
  EXPECT_EQ(check_error(one(uniform_int("level", 1)), 1000), "");
  EXPECT_EQ(check_error(one(uniform_int("level", 1)), 0), "");
  Field two = uniform_int("level", 1);
  std::get<0>(two.data).push_back(2);
  EXPECT_EQ(check_error(one(two), 2), "point field 'level' has 2 values, expected 1 × 1");
  Field none = uniform_int("level", 1);
  std::get<0>(none.data).clear();
  EXPECT_EQ(check_error(one(none), 2), "point field 'level' has 0 values, expected 1 × 1");
  Field uniform3{"color", 3, std::vector<double>{1, 2, 3}, true};
  EXPECT_EQ(check_error(one(uniform3), 50), "");
}

TEST(FieldsCheck, BadComponentCounts) {
  EXPECT_EQ(check_error(one(real_field("v", {}, 0)), 3), "point field 'v' has 0 components, expected 1 to 3");
  EXPECT_EQ(check_error(one(real_field("v", std::vector<double>(12, 0.0), 4)), 3),
            "point field 'v' has 4 components, expected 1 to 3");
}

TEST(FieldsCheck, BadNames) {
  const std::string expected_tail = ": a field name is 1 to 64 letters, digits or underscores";
  EXPECT_EQ(check_error(one(int_field("", {1})), 1), "point field ''" + expected_tail);
  EXPECT_EQ(check_error(one(int_field("two words", {1})), 1), "point field 'two words'" + expected_tail);
  EXPECT_EQ(check_error(one(int_field("a\"b", {1})), 1), "point field 'a\"b'" + expected_tail);
  EXPECT_EQ(check_error(one(int_field(std::string(65, 'x'), {1})), 1),
            "point field '" + std::string(65, 'x') + "'" + expected_tail);
  EXPECT_NE(check_error(one(int_field("a<b", {1})), 1), "");
  EXPECT_NE(check_error(one(int_field("é", {1})), 1), "");
}

TEST(FieldsCheck, NonFiniteFloatValues) {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(check_error(one(real_field("thickness", {1, nan, 3})), 3, "face"),
            "face field 'thickness' has a non-finite value");
  EXPECT_EQ(check_error(one(real_field("thickness", {1, 2, -inf})), 3),
            "point field 'thickness' has a non-finite value");
}

TEST(FieldsCheck, NamesTheFirstBadField) {
  Fields fs;
  fs.set(int_field("good", {1, 2}));
  fs.set(int_field("bad", {1}));
  fs.set(int_field("", {1, 2}));
  EXPECT_EQ(check_error(fs, 2), "point field 'bad' has 1 values, expected 2 × 1");
}
