// How an output was made, recorded in it: the selfsim version, the recipe (absolute path and SHA-256),
// the --set values and seed of the run, and the file's name in the output folder. Written into every
// format that has a place for text (VTK FieldData, an SVG or OBJ comment, a PLY header comment, 3MF
// metadata) and beside the others (NAME.stl.json, NAME.vdb.json); read back by `selfsim info` and `selfsim rerun`.
// Nothing in it changes from run to run (no clock, no host, no output folder), so runs repeat byte for byte.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>

namespace selfsim::io {

struct Provenance {
  std::string version;                      // selfsim's
  std::string recipe;                       // its absolute path
  std::string sha256;                       // of the recipe's bytes
  std::map<std::string, std::string> sets;  // --set key=value
  long long seed = 0;
  std::string name;  // the file's name inside the run's output folder ("c.svg", "growth/growth_003.vtp")
};

// One line of JSON. It never holds "--", so it can sit inside an XML comment.
std::string provenance_json(const Provenance& p);

// Parses provenance_json's text; nullopt for text that does not begin with '{' (no record). Throws Error
// naming the field and what was expected for anything else provenance_json would not write: a string that
// is not strict JSON (a bad \u escape, a lone surrogate, a raw control character, raw bytes that are not
// UTF-8) or holds a NUL, a value of another type, a field given twice, a seed outside [0, 2^63) (what
// --seed takes), no recipe, a byte order mark (provenance_parse.cpp).
std::optional<Provenance> parse_provenance(const std::string& json);

// The provenance recorded in (or, for .stl, beside) the file; nullopt when there is none. Throws Error
// when the file cannot be read or its record is malformed ("cannot read 'FILE': its provenance record: ...").
std::optional<Provenance> read_provenance(const std::filesystem::path& file);

// The key under which formats hold it: "selfsim_provenance".
inline constexpr const char* provenance_key = "selfsim_provenance";

// Formats whose provenance goes beside them, as NAME.json: no place for text inside.
bool provenance_beside(const std::string& extension);

}  // namespace selfsim::io
