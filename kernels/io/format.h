// The format registry: for each file extension, which values it holds, which save() options it reads, and
// its writer. save(), the CLI's help and the README's formats table all come from here, so adding a format
// is one writer file plus one line in format.cpp.
#pragma once

#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "kernels/base/progress.h"
#include "kernels/geom/mesh.h"
#include "kernels/geom/polyline.h"
#include "kernels/io/output_file.h"

namespace selfsim::io {

enum class ValueKind { Curve, Curve3, Mesh };

// "curve", "3D curve", "mesh": for messages.
const char* kind_name(ValueKind k);

// A value to write, whichever kind it is.
using ValueRef = std::variant<const Polyline*, const Polyline3*, const Mesh*>;
ValueKind kind_of(const ValueRef& v);

struct SaveOptions;
using Writer = void (*)(const ValueRef& value, OutputFile& out, const SaveOptions& opt, Progress& progress);

struct Format {
  std::string extension;             // with the dot: ".vtp"
  std::string description;           // what opens it: "VTK PolyData: ParaView"
  std::vector<ValueKind> accepts;    // the values it can hold
  std::vector<std::string> options;  // the save() options it reads
  Writer write;

  bool holds(ValueKind k) const;
};

// Every format, in the order the help lists them.
const std::vector<Format>& formats();

// The format of a file name's extension, or null.
const Format* find_format(std::string_view extension);

// The format for saving a value of kind k as `name`; throws Error for an unknown extension (listing the
// known ones) or one that cannot hold k (listing those that can).
const Format& format_for(const std::string& name, ValueKind k);

// Throws Error if any of `given` (option names the caller set) is not an option of f: "option 'stroke' does
// not apply to '.stl' files (it is an option of '.svg'; '.stl' takes no options)". Names that are no
// format's option are left to the caller's unknown-option check.
void check_options(const Format& f, const std::vector<std::string>& given);

}  // namespace selfsim::io
