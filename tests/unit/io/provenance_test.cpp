// The provenance record read back strictly: what provenance_json writes reads back whole (non-UTF-8 bytes,
// control characters, "--"), and a string JSON would refuse, or one holding a NUL, is an Error naming the
// field instead of a character made up (\uzzzz read as a NUL, which cut the recipe path for rerun).
#include "kernels/io/provenance/provenance.h"

#include <gtest/gtest.h>

#include <string>

#include "kernels/base/error.h"

using namespace selfsim;

namespace {

std::string record(const std::string& recipe, const std::string& set = "{\"level\": \"5\"}",
                   const std::string& seed = "3") {
  return "{\"selfsim\": \"0.1.0\", \"recipe\": \"" + recipe + "\", \"sha256\": \"ab\", \"set\": " + set +
         ", \"seed\": " + seed + ", \"name\": \"c.svg\"}";
}

// The message of the Error parse_provenance throws, or "no error".
std::string refusal(const std::string& json) {
  try {
    io::parse_provenance(json);
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST(Provenance, WhatIsWrittenReadsBackWhole) {
  io::Provenance p;
  p.version = "0.1.0";
  p.recipe = std::string("/a--b/\xff\xfe\x01 \"q\"\\ \xc3\xa9/r.lua");  // not UTF-8, a control, quotes
  p.sha256 = "0123";
  p.sets = {{"level", "5"}, {"word", "a\tb\nc"}};
  p.seed = 9223372036854775807LL;
  p.name = "growth/g_003.vtp";
  const auto back = io::parse_provenance(io::provenance_json(p));
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(back->recipe, p.recipe);
  EXPECT_EQ(back->sets, p.sets);
  EXPECT_EQ(back->seed, p.seed);
  EXPECT_EQ(back->name, p.name);
  EXPECT_EQ(back->version, p.version);
}

TEST(Provenance, JsonEscapesOfOtherWritersRead) {
  const auto p = io::parse_provenance(record("/x\\/\\u00e9\\u20ac\\ud83d\\ude00.lua"));
  ASSERT_TRUE(p.has_value());
  // \u00e9 is the byte 0xe9 (how selfsim writes a byte of a non-UTF-8 name); above U+00FF, UTF-8.
  EXPECT_EQ(p->recipe, "/x/\xe9\xe2\x82\xac\xf0\x9f\x98\x80.lua");
}

TEST(Provenance, BadEscapesAreErrorsNamingTheField) {
  EXPECT_EQ(refusal(record("/a\\uzzzz.lua")),
            "the field \"recipe\" holds a bad escape '\\uzzzz' (\\u takes 4 hex digits)");
  EXPECT_EQ(refusal(record("/a\\u12")), "the field \"recipe\" holds a bad escape '\\u12\",' (\\u takes 4 hex digits)");
  EXPECT_EQ(refusal(record("/a\\q")), "the field \"recipe\" holds an unknown escape '\\q'");
  EXPECT_EQ(refusal(record("/a\\udc00")), "the field \"recipe\" holds a lone surrogate '\\udc00'");
  EXPECT_EQ(refusal(record("/a\\ud800.lua")), "the field \"recipe\" holds a lone surrogate '\\ud800'");
  EXPECT_EQ(refusal(record("/a\\ud800\\u0041")),
            "the field \"recipe\" holds a lone surrogate '\\ud800' (followed by '\\u0041')");
  EXPECT_EQ(refusal(record("/a\tb")),
            "the field \"recipe\" holds a raw control character (byte 9); JSON writes it as an escape");
  EXPECT_EQ(refusal("{\"recipe\": \"/a"), "the field \"recipe\" has no closing quote");
}

TEST(Provenance, NulIsRefusedInEveryField) {
  EXPECT_EQ(refusal(record("/r.lua\\u0000/../../evil.lua")), "the field \"recipe\" holds a NUL character");
  EXPECT_EQ(refusal(record("/r.lua", "{\"lev\\u0000el\": \"5\"}")), "a key of \"set\" holds a NUL character");
  EXPECT_EQ(refusal(record("/r.lua", "{\"level\": \"5\\u0000\"}")),
            "the \"set\" value of 'level' holds a NUL character");
  EXPECT_EQ(refusal("{\"rec\\u0000ipe\": \"/r.lua\"}"), "a key of the record holds a NUL character");
  std::string name = record("/r.lua");
  name.replace(name.find("c.svg"), 5, "c.svg\\u0000x");
  EXPECT_EQ(refusal(name), "the field \"name\" holds a NUL character");
}

TEST(Provenance, FieldsGivenTwiceAndSeedsOutOfRangeAreErrors) {
  EXPECT_EQ(refusal("{\"recipe\": \"/a.lua\", \"recipe\": \"/b.lua\"}"), "the field \"recipe\" is given twice");
  EXPECT_EQ(refusal(record("/r.lua", "{\"a\": \"1\", \"a\": \"2\"}")), "the \"set\" key 'a' is given twice");
  EXPECT_EQ(io::parse_provenance(record("/r.lua", "{}", "9223372036854775807"))->seed, 9223372036854775807LL);
}

// A record is there once the text begins with '{': what provenance_json would not write is an Error naming
// the field and what was expected, never "no record" (rerun said "records no recipe" of a number in "set").
TEST(Provenance, ValuesARunWouldRefuseAreErrorsNamingTheField) {
  const std::string range = ", not a whole number in [0, 2^63) (what --seed takes)";
  EXPECT_EQ(refusal(record("/r.lua", "{}", "-1")), "the field \"seed\" holds -1" + range);
  EXPECT_EQ(refusal(record("/r.lua", "{}", "-9223372036854775808")),
            "the field \"seed\" holds -9223372036854775808" + range);
  EXPECT_EQ(refusal(record("/r.lua", "{}", "9223372036854775808")),
            "the field \"seed\" holds 9223372036854775808" + range + ": it is 2^63 or more");
  EXPECT_EQ(refusal(record("/r.lua", "{}", "1.0")), "the field \"seed\" holds 1.0" + range);
  EXPECT_EQ(refusal(record("/r.lua", "{}", "1e3")), "the field \"seed\" holds 1e3" + range);
  EXPECT_EQ(refusal(record("/r.lua", "{}", "+1")), "the field \"seed\" holds +1" + range);
  EXPECT_EQ(refusal(record("/r.lua", "{}", "\"3\"")), "the field \"seed\" holds \"3\"" + range);
  EXPECT_EQ(refusal(record("/r.lua", "{\"level\": 5}")), "the \"set\" value of 'level' is 5, not a string");
  EXPECT_EQ(refusal(record("/r.lua", "{\"level\": true}")), "the \"set\" value of 'level' is true, not a string");
  EXPECT_EQ(refusal(record("/r.lua", "{\"level\": null}")), "the \"set\" value of 'level' is null, not a string");
  EXPECT_EQ(refusal(record("/r.lua", "{\"level\": \"5\" \"x\"}")),
            "expected ',' or '}' after the last \"set\" value, found \"x\"");
  EXPECT_EQ(refusal(record("/r.lua", "[\"5\"]")), "the field \"set\" is [, not an object of strings");
  EXPECT_EQ(refusal("{\"recipe\": 7}"), "the field \"recipe\" is 7, not a string");
  EXPECT_EQ(refusal("{\"recipe\" \"/r.lua\"}"), "expected ':' after the key \"recipe\", found \"/r.lua\"");
  EXPECT_EQ(refusal("{\"recipe\": \"/r.lua\""),
            "expected ',' or '}' after the field \"recipe\", found the end of the record");
  EXPECT_EQ(refusal("{5: 1}"), "a key of the record is 5, not a string");
  EXPECT_EQ(refusal("\xef\xbb\xbf" + record("/r.lua")),
            "expected '{' at the start of the record, found a UTF-8 byte order mark (bytes EF BB BF)");
  EXPECT_EQ(refusal(record("")), "the field \"recipe\" is empty");
  EXPECT_EQ(refusal("{\"name\": \"c.svg\"}"), "the record has no field \"recipe\"");
}

// selfsim writes a byte of a string that is not UTF-8 as \u0080-\u00ff, so raw bytes that are not UTF-8
// never stand in a record it wrote: they are refused, as the \ud800 escape is, naming the field.
TEST(Provenance, RawBytesThatAreNotUtf8AreErrorsNamingTheField) {
  const std::string tail = "; a record is UTF-8 and writes such a byte as an escape, \\u00";
  EXPECT_EQ(refusal(record("/a\xff.lua")), "the field \"recipe\" holds a byte that is not UTF-8 (0xff)" + tail + "ff");
  EXPECT_EQ(refusal(record("/a\xc0\x80.lua")),
            "the field \"recipe\" holds a byte that is not UTF-8 (0xc0)" + tail + "c0");
  EXPECT_EQ(refusal(record("/a\xed\xa0\x80.lua")),
            "the field \"recipe\" holds a byte that is not UTF-8 (0xed)" + tail + "ed");
  EXPECT_EQ(refusal(record("/r.lua", "{\"\xe9\": \"5\"}")),
            "a key of \"set\" holds a byte that is not UTF-8 (0xe9)" + tail + "e9");
  EXPECT_EQ(refusal(record("/a\xc3")), "the field \"recipe\" holds a byte that is not UTF-8 (0xc3)" + tail + "c3");
  // Well-formed UTF-8 reads as it is, beside the escapes of bytes that are not.
  EXPECT_EQ(io::parse_provenance(record("/\xc3\xa9\xf0\x9f\x98\x80\\u00e9.lua"))->recipe,
            "/\xc3\xa9\xf0\x9f\x98\x80\xe9.lua");
}

TEST(Provenance, TextNotBeginningWithABraceIsNoRecord) {
  EXPECT_FALSE(io::parse_provenance(""));
  EXPECT_FALSE(io::parse_provenance("[1]"));
  EXPECT_FALSE(io::parse_provenance("selfsim made this"));
}
