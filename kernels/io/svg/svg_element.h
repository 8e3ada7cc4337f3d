// What an SVG element's start tag means for drawing, given the elements it is inside: whether it is an SVG
// element (XML namespaces), whether it is drawn, and the matrix from its coordinates to selfsim's.
//
// What is drawn: paths whose every ancestor is an SVG <svg>, <g>, <a> or <switch> (so nothing inside <defs>,
// <symbol>, <clipPath>, <mask>, <pattern>, <marker>, <text> or an element of another namespace), with no
// display none on them or an ancestor, and visible: visibility is inherited, hidden and collapse hide, and a
// child may say visible again. Each is a presentation attribute or a declaration in the style attribute,
// the declaration winning, values trimmed and in any case. All children of a <switch> are read.
//
// Namespaces, the simplest rule that reads real files correctly: an element's name is resolved with the
// xmlns and xmlns:prefix declarations in scope (its own tag's included); it is an SVG element when that
// gives http://www.w3.org/2000/svg, or when it has no prefix and no default namespace is declared at all
// (SVG files written without xmlns, which SVG tools read). A prefix that is not declared, a name with two
// colons and the xml prefix are not SVG.
// Attributes are recognised by their unprefixed names (transform, style, display, visibility), as SVG
// defines them; a prefixed attribute (foo:transform) is another attribute.
//
// Coordinates: SVG's y axis points down, selfsim's up, so the matrix of the root's parent is scale(1, -1).
// That undoes the scale(1,-1) group selfsim writes (a saved curve reads back as it was), and a drawing
// from elsewhere reads the way up it is seen. viewBox, x and y of <svg> elements and <use> references are
// not applied: the points are in the root's user units. Style sheets (<style>) are not read; a style
// attribute's display, visibility, stroke and fill are. Stroke and fill are inherited as in SVG; a colour
// given as a CSS name, #rgb or #rrggbb is read (other forms, gradients and currentColor count as none).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "kernels/io/svg/svg_transform.h"
#include "kernels/io/text/colour.h"

namespace selfsim::io {

// The attributes of one start tag that matter for drawing, values as written (character references undone).
struct SvgTag {
  std::optional<std::string> transform, style, display, visibility, stroke, fill;
  std::vector<std::pair<std::string, bool>> namespaces;  // xmlns ("") and xmlns:prefix: bound to SVG?

  // The field an attribute of this name is kept in, or nullptr for one that does not matter for drawing
  // (xmlns is kept apart, in `namespaces`).
  std::optional<std::string>* slot(const std::string& attribute);
};

struct SvgElement {
  std::string local;    // the name without its prefix
  bool svg = false;     // in SVG's namespace
  bool drawn = false;   // a path that is drawn if visible, or a container whose content may be
  bool visible = true;  // its computed visibility, inherited (a child may be visible again)
  Affine2 to_selfsim;   // its coordinates (inside its own transform) → selfsim's
  // Its stroke and fill as set on it or inherited (lower case, "" where nothing sets them), and the colour a
  // path of it is drawn in: its stroke, else (a stroke of none or not a colour) its fill, else black.
  std::string stroke, fill;
  Rgb colour() const;
};

class SvgScopes {
 public:
  // The element a start tag opens inside the innermost open one (none: the root). Throws Error for a
  // malformed transform of an element that may be drawn, or a value with a malformed character reference.
  SvgElement open(std::string_view name, const SvgTag& tag) const;
  void push(const SvgElement& e, const SvgTag& tag);  // its content follows (not a self-closing tag)
  void pop();                                         // its end tag
  bool content_drawn() const { return scopes_.empty() || scopes_.back().drawn; }

 private:
  struct Scope {
    bool drawn, visible;
    Affine2 to_selfsim;
    std::size_t namespaces;  // declarations in scope inside it
    std::string stroke, fill;
  };
  bool bound_to_svg(const std::string& prefix, const SvgTag& tag) const;

  std::vector<Scope> scopes_;
  std::vector<std::pair<std::string, bool>> namespaces_;  // declarations in scope, innermost last
};

// An attribute value with XML's character and entity references (&amp; &#38; &#x26; ...) replaced; throws
// Error naming `attribute` for a malformed one.
std::string xml_unescaped(std::string_view value, const std::string& attribute);

}  // namespace selfsim::io
