// A run's results record (results.json): what results_json writes reads back exactly (the shortest text of
// each double, the names in order), and anything else is refused naming what was expected: a name outside
// the rule, one given twice, a number JSON would not write or that is not finite, no provenance record.
#include "kernels/io/run_results.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "kernels/base/error.h"
#include "kernels/io/provenance/provenance.h"

using namespace selfsim;

namespace {

std::string provenance() {
  io::Provenance p;
  p.version = "0.1.0";
  p.recipe = "/r.lua";
  p.sha256 = "ab";
  p.sets = {{"x", "2"}};
  p.name = "results.json";
  return io::provenance_json(p);
}

std::string refusal(const std::string& text) {
  try {
    io::parse_results(text);
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

TEST(RunResults, RoundTripsExactly) {
  const std::vector<io::RunResult> given{
      {"sum", 0.1 + 0.2}, {"a.b-c_d", -1e-300}, {"_big", 1.7976931348623157e308}, {"whole", 4}};
  const std::string text = io::results_json(given, provenance());
  EXPECT_NE(text.find("\"sum\": 0.30000000000000004"), std::string::npos) << text;
  EXPECT_NE(text.find("\"whole\": 4}"), std::string::npos) << text;
  const std::vector<io::RunResult> back = io::parse_results(text);
  ASSERT_EQ(back.size(), given.size());
  for (std::size_t i = 0; i < given.size(); ++i) {
    EXPECT_EQ(back[i].name, given[i].name);
    EXPECT_EQ(back[i].value, given[i].value);  // bit for bit, not near
  }
  EXPECT_TRUE(io::parse_results("{\"results\": {}, \"provenance\": " + provenance() + "}").empty());
}

TEST(RunResults, NameRule) {
  EXPECT_EQ(io::result_name_problem("dimension"), "");
  EXPECT_EQ(io::result_name_problem("_a1.b-c"), "");
  EXPECT_EQ(io::result_name_problem(""), "is empty");
  EXPECT_EQ(io::result_name_problem("1d"), "must start with a letter or '_'");
  EXPECT_EQ(io::result_name_problem(".hidden"), "must start with a letter or '_'");
  EXPECT_NE(io::result_name_problem("a/b").find("holds '/'"), std::string::npos);
  EXPECT_NE(io::result_name_problem("a,b").find("holds ','"), std::string::npos);
  EXPECT_NE(io::result_name_problem("a\nb").find("holds '?'"), std::string::npos);
  EXPECT_EQ(io::result_name_problem(std::string(64, 'a')), "");
  EXPECT_EQ(io::result_name_problem(std::string(65, 'a')), "is 65 bytes long; at most 64");
  EXPECT_THROW(io::results_json({{"a b", 1}}, provenance()), Error);
  EXPECT_THROW(io::results_json({{"a", NAN}}, provenance()), Error);
  EXPECT_THROW(io::results_json({{"a", INFINITY}}, provenance()), Error);
}

TEST(RunResults, RefusesWhatItDoesNotWrite) {
  const std::string tail = "}, \"provenance\": " + provenance() + "}";
  auto starts = [](const std::string& text, const std::string& prefix) {
    EXPECT_TRUE(text.starts_with(prefix)) << text;
  };
  EXPECT_EQ(refusal("{\"results\": {\"a\": 1, \"a\": 2" + tail), "the result \"a\" is given twice");
  EXPECT_EQ(refusal("{\"results\": {\"a\": nan" + tail), "expected a finite number for \"a\", found 'nan}, \"prove'");
  for (const char* bad : {"1e999", "01", ".5", "\"1\"", "-", "1.", "1e"})
    starts(refusal("{\"results\": {\"a\": " + std::string(bad) + tail), "expected a finite number for \"a\", found");
  starts(refusal("{\"results\": {\"a b\": 1" + tail), "the result name \"a b\" holds ' '");
  EXPECT_EQ(refusal("{\"results\": {\"a\": 1}}"), "expected ',' after \"results\", found '}'");
  starts(refusal("{\"results\": {\"a\": 1}, \"provenance\": {\"selfsim\": 3}}"), "the field");
  EXPECT_EQ(refusal("[]"), "expected '{' at the start, found '[]'");
  EXPECT_EQ(refusal("{\"results\": {\"a\": 1" + tail + "x"), "expected '}' at the end");
  EXPECT_EQ(refusal("{\"results\": {}}"), "expected ',' after \"results\", found '}'");
}

// A results.json edited by hand with more results than a run may give (each a column and a plot of the
// sweep's: 200,000 took minutes to collect) is refused; max_results of them read back.
TEST(RunResults, AtMostMaxResults) {
  std::vector<io::RunResult> given;
  for (std::size_t i = 0; i < io::max_results; ++i) given.push_back({"r" + std::to_string(i), 1.0 * i});
  const std::string text = io::results_json(given, provenance());
  EXPECT_EQ(io::parse_results(text).size(), io::max_results);
  given.push_back({"one_more", 1});
  EXPECT_EQ(refusal(io::results_json(given, provenance())),
            "it holds more than " + std::to_string(io::max_results) + " results, the most a run gives");
}

}  // namespace
