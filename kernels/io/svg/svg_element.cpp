#include "kernels/io/svg/svg_element.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <optional>

#include "kernels/base/error.h"
#include "kernels/base/lower_case.h"
#include "kernels/io/read_error.h"
#include "kernels/io/text/hex_digit.h"
#include "kernels/io/text/xml_text.h"

namespace selfsim::io {

std::optional<std::string>* SvgTag::slot(const std::string& attribute) {
  if (attribute == "transform") return &transform;
  if (attribute == "style") return &style;
  if (attribute == "display") return &display;
  if (attribute == "visibility") return &visibility;
  if (attribute == "stroke") return &stroke;
  if (attribute == "fill") return &fill;
  return nullptr;
}

namespace {

constexpr std::size_t max_namespaces = 4096;  // declarations in scope at once

// The elements whose content is drawn where it stands. Not that of <defs>, <symbol>, <clipPath>, <mask>,
// <pattern> or <marker> (definitions, drawn where something refers to them), nor of <text>, <path>,
// <foreignObject>, <title>, <metadata> or any other element.
bool container(const std::string& local) { return local == "svg" || local == "g" || local == "a" || local == "switch"; }

std::string trimmed(std::string_view s) {
  while (!s.empty() && xml_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && xml_space(s.back())) s.remove_suffix(1);
  return std::string(s);
}

// The value of a property in a style attribute ("fill:none; display : none !important"), lower case; the
// last declaration wins, as in CSS.
std::optional<std::string> style_property(std::string_view style, std::string_view property) {
  std::optional<std::string> value;
  while (!style.empty()) {
    const std::size_t semicolon = std::min(style.find(';'), style.size());
    const std::string_view declaration = style.substr(0, semicolon);
    style.remove_prefix(std::min(semicolon + 1, style.size()));
    const std::size_t colon = declaration.find(':');
    if (colon == std::string_view::npos || lower_case(trimmed(declaration.substr(0, colon))) != property) continue;
    std::string v = lower_case(trimmed(declaration.substr(colon + 1)));
    if (v.size() >= 10 && v.compare(v.size() - 10, 10, "!important") == 0) v = trimmed(v.substr(0, v.size() - 10));
    value = v;
  }
  return value;
}

// A presentation property as the element sets it: the style attribute's declaration, else the attribute.
std::optional<std::string> property(const SvgTag& tag, const std::optional<std::string>& attribute,
                                    std::string_view name) {
  if (tag.style)
    if (auto v = style_property(*tag.style, name)) return v;
  if (attribute) return lower_case(trimmed(*attribute));
  return std::nullopt;
}

int digit_value(char c, bool hex) {
  if (hex) return hex_digit(c);
  return c >= '0' && c <= '9' ? c - '0' : -1;
}

void put_utf8(std::string& s, unsigned long code) {
  if (code < 0x80) {
    s += static_cast<char>(code);
  } else if (code < 0x800) {
    s += static_cast<char>(0xC0 | (code >> 6));
    s += static_cast<char>(0x80 | (code & 0x3F));
  } else if (code < 0x10000) {
    s += static_cast<char>(0xE0 | (code >> 12));
    s += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
    s += static_cast<char>(0x80 | (code & 0x3F));
  } else {
    s += static_cast<char>(0xF0 | (code >> 18));
    s += static_cast<char>(0x80 | ((code >> 12) & 0x3F));
    s += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
    s += static_cast<char>(0x80 | (code & 0x3F));
  }
}

}  // namespace

std::string xml_unescaped(std::string_view value, const std::string& attribute) {
  std::string s;
  for (std::size_t i = 0; i < value.size(); ++i) {
    if (value[i] != '&') {
      s += value[i];
      continue;
    }
    const std::size_t end = value.find(';', i);
    const std::string_view ref = value.substr(i + 1, end == std::string_view::npos ? 0 : end - i - 1);
    auto bad = [&] { return Error("a malformed character reference in the '" + shown(attribute) + "' attribute"); };
    if (end == std::string_view::npos || ref.empty()) throw bad();
    if (ref == "amp" || ref == "lt" || ref == "gt" || ref == "quot" || ref == "apos") {
      s += ref == "amp" ? '&' : ref == "lt" ? '<' : ref == "gt" ? '>' : ref == "quot" ? '"' : '\'';
    } else if (ref[0] == '#' && ref.size() <= 10) {
      const bool hex = ref.size() > 1 && ref[1] == 'x';
      const std::string_view digits = ref.substr(hex ? 2 : 1);
      unsigned long code = 0;
      for (char c : digits) {
        const int d = digit_value(c, hex);
        if (d < 0) throw bad();
        code = code * (hex ? 16 : 10) + static_cast<unsigned long>(d);
      }
      if (digits.empty() || code == 0 || code > 0x10FFFF || (code >= 0xD800 && code < 0xE000)) throw bad();
      put_utf8(s, code);
    } else {
      if (ref[0] == '#') throw bad();
      throw Error("the '" + shown(attribute) + "' attribute refers to the entity '&" + shown(ref) +
                  ";', which is not read (entities declared in a DOCTYPE are not expanded)");
    }
    i = end;
  }
  return s;
}

bool SvgScopes::bound_to_svg(const std::string& prefix, const SvgTag& tag) const {
  for (const auto& [p, svg] : tag.namespaces)
    if (p == prefix) return svg;
  for (auto it = namespaces_.rbegin(); it != namespaces_.rend(); ++it)
    if (it->first == prefix) return it->second;
  return prefix.empty();  // no default namespace declared: SVG; an undeclared prefix: not
}

SvgElement SvgScopes::open(std::string_view name, const SvgTag& tag) const {
  const Scope parent = scopes_.empty() ? Scope{true, true, Affine2{1, 0, 0, -1, 0, 0}, 0, {}, {}} : scopes_.back();
  SvgElement e;
  const std::size_t colon = name.find(':');
  e.local = std::string(colon == std::string_view::npos ? name : name.substr(colon + 1));
  const std::string prefix(colon == std::string_view::npos ? std::string_view{} : name.substr(0, colon));
  e.svg = e.local.find(':') == std::string::npos && !e.local.empty() &&
          (colon == std::string_view::npos || !prefix.empty()) && prefix != "xml" && prefix != "xmlns" &&
          bound_to_svg(prefix, tag);
  e.drawn = parent.drawn && e.svg && (e.local == "path" || container(e.local)) &&
            property(tag, tag.display, "display") != "none";
  const std::optional<std::string> visibility = property(tag, tag.visibility, "visibility");
  e.visible = visibility == "visible"                              ? true
              : visibility == "hidden" || visibility == "collapse" ? false
                                                                   : parent.visible;
  e.stroke = property(tag, tag.stroke, "stroke").value_or(parent.stroke);
  e.fill = property(tag, tag.fill, "fill").value_or(parent.fill);
  if (e.drawn) {
    e.to_selfsim = tag.transform ? parent.to_selfsim.after(parse_svg_transform(*tag.transform)) : parent.to_selfsim;
    if (!e.to_selfsim.finite()) throw Error("the transforms of an element and its ancestors overflow");
  }
  return e;
}

void SvgScopes::push(const SvgElement& e, const SvgTag& tag) {
  if (namespaces_.size() + tag.namespaces.size() > max_namespaces)
    throw Error("more than " + std::to_string(max_namespaces) + " XML namespace declarations in scope");
  namespaces_.insert(namespaces_.end(), tag.namespaces.begin(), tag.namespaces.end());
  scopes_.push_back({e.drawn && e.local != "path", e.visible, e.to_selfsim, namespaces_.size(), e.stroke, e.fill});
}

namespace {

// A paint as SVG and CSS write it: a colour name, #rgb, #rrggbb, or rgb()/rgba() of three numbers (0 to 255)
// or percentages, by commas or spaces, an alpha after them ignored, each clamped as CSS does. Inkscape and
// many plotting tools write rgb(): read as no colour, such a stroke was drawn black.
std::optional<Rgb> paint_rgb(const std::string& text) {
  if (auto c = colour_rgb(text)) return c;
  const std::string t = lower_case(text);
  const std::size_t open = t.find('(');
  if (open == std::string::npos || t.back() != ')' ||
      (t.compare(0, open, "rgb") != 0 && t.compare(0, open, "rgba") != 0))
    return std::nullopt;
  Rgb c{};
  const char* at = t.c_str() + open + 1;
  for (int j = 0; j < 3; ++j) {
    while (*at == ' ' || *at == '\t' || (j > 0 && *at == ',')) ++at;
    char* end = nullptr;
    const double v = std::strtod(at, &end);
    if (end == at || !std::isfinite(v)) return std::nullopt;
    const bool percent = *end == '%';
    c[static_cast<std::size_t>(j)] = std::clamp(percent ? v / 100 : v / 255, 0.0, 1.0);
    at = end + (percent ? 1 : 0);
  }
  return c;
}

}  // namespace

Rgb SvgElement::colour() const {
  if (auto c = paint_rgb(stroke)) return *c;
  if (fill != "none")
    if (auto c = paint_rgb(fill)) return *c;
  return {0, 0, 0};  // SVG's own default: a black fill
}

void SvgScopes::pop() {
  scopes_.pop_back();
  namespaces_.resize(scopes_.empty() ? 0 : scopes_.back().namespaces);
}

}  // namespace selfsim::io
