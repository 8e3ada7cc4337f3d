// The first bytes of one file inside a zip held in memory (a .3mf is a zip): for the few things selfsim must
// see in a package that lib3mf does not hand back, such as the text of a 3MF model's unit attribute when
// lib3mf only says it is invalid. Stored and deflated entries; nothing is trusted (every offset and size is
// checked against the bytes, and at most `limit` bytes are inflated).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace selfsim::io {

// Up to `limit` bytes of the entry named `name` (compared without regard to ASCII case, as OPC names are;
// a leading '/' ignored), or nullopt when the zip has no such entry or it cannot be read.
std::optional<std::string> zip_part_head(std::string_view zip, std::string_view name, std::size_t limit);

// The value of attribute `attribute` on the first element named `element` (any namespace prefix) in XML
// text, or nullopt when there is none. Entities are left as they are.
std::optional<std::string> xml_attribute(std::string_view xml, std::string_view element, std::string_view attribute);

}  // namespace selfsim::io
