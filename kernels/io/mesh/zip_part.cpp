#include "kernels/io/mesh/zip_part.h"

#include <zlib.h>

#include <algorithm>
#include <cstdint>

namespace selfsim::io {

namespace {

std::uint32_t le(std::string_view s, std::size_t at, int bytes) {
  std::uint32_t v = 0;
  for (int k = bytes - 1; k >= 0; --k) v = v << 8 | static_cast<unsigned char>(s[at + static_cast<std::size_t>(k)]);
  return v;
}

bool same_name(std::string_view a, std::string_view b) {
  if (!a.empty() && a[0] == '/') a.remove_prefix(1);
  if (!b.empty() && b[0] == '/') b.remove_prefix(1);
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           const auto lower = [](char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; };
           return lower(x) == lower(y);
         });
}

// Up to `limit` bytes inflated from raw deflate data; what came out before an error (enough for a head).
std::string inflate_head(std::string_view data, std::size_t limit) {
  z_stream z{};
  if (inflateInit2(&z, -MAX_WBITS) != Z_OK) return {};
  std::string out(limit, '\0');
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(data.data()));
  z.avail_in = static_cast<uInt>(std::min<std::size_t>(data.size(), UINT32_MAX));
  z.next_out = reinterpret_cast<Bytef*>(out.data());
  z.avail_out = static_cast<uInt>(limit);
  inflate(&z, Z_FINISH);
  out.resize(limit - z.avail_out);
  inflateEnd(&z);
  return out;
}

}  // namespace

std::optional<std::string> zip_part_head(std::string_view zip, std::string_view name, std::size_t limit) {
  limit = std::min<std::size_t>(limit, UINT32_MAX);
  // The end of central directory record: 22 bytes, then a comment of up to 65535.
  if (zip.size() < 22) return std::nullopt;
  std::size_t end = zip.size() - 22;
  const std::size_t lowest = zip.size() > 22 + 65535 ? zip.size() - 22 - 65535 : 0;
  while (le(zip, end, 4) != 0x06054b50) {
    if (end == lowest) return std::nullopt;
    --end;
  }
  const std::size_t count = le(zip, end + 10, 2);
  std::size_t at = le(zip, end + 16, 4);
  for (std::size_t k = 0; k < count; ++k) {
    if (at > zip.size() || zip.size() - at < 46 || le(zip, at, 4) != 0x02014b50) return std::nullopt;
    const std::uint32_t method = le(zip, at + 10, 2), packed = le(zip, at + 20, 4);
    const std::size_t n = le(zip, at + 28, 2), extra = le(zip, at + 30, 2), comment = le(zip, at + 32, 2);
    const std::size_t local = le(zip, at + 42, 4);
    if (zip.size() - at - 46 < n) return std::nullopt;
    const std::string_view entry = zip.substr(at + 46, n);
    at += 46 + n + extra + comment;
    if (!same_name(entry, name)) continue;
    if (local > zip.size() || zip.size() - local < 30 || le(zip, local, 4) != 0x04034b50) return std::nullopt;
    const std::size_t data = local + 30 + le(zip, local + 26, 2) + le(zip, local + 28, 2);
    if (data > zip.size()) return std::nullopt;
    const std::string_view bytes = zip.substr(data, std::min<std::size_t>(packed, zip.size() - data));
    if (method == 0) return std::string(bytes.substr(0, limit));
    if (method == 8) return inflate_head(bytes, limit);
    return std::nullopt;
  }
  return std::nullopt;
}

std::optional<std::string> xml_attribute(std::string_view xml, std::string_view element, std::string_view attribute) {
  for (std::size_t at = 0; (at = xml.find('<', at)) != std::string_view::npos; ++at) {
    if (xml.substr(at, 4) == "<!--") {  // a comment may hold anything
      at = xml.find("-->", at);
      if (at == std::string_view::npos) return std::nullopt;
      continue;
    }
    std::size_t name_end = xml.find_first_of(" \t\r\n/>", at + 1);
    if (name_end == std::string_view::npos) return std::nullopt;
    std::string_view tag = xml.substr(at + 1, name_end - at - 1);
    if (const std::size_t colon = tag.find(':'); colon != std::string_view::npos) tag.remove_prefix(colon + 1);
    if (tag != element) continue;
    const std::size_t close = xml.find('>', name_end);
    const std::string_view attrs = xml.substr(name_end, close == std::string_view::npos ? xml.npos : close - name_end);
    // Each attribute: a name, '=', a quoted value (an attribute of the same name inside another's value
    // cannot be taken: values are skipped whole).
    for (std::size_t i = 0; i < attrs.size();) {
      const std::size_t name_at = attrs.find_first_not_of(" \t\r\n/", i);
      if (name_at == std::string_view::npos) break;
      const std::size_t eq = attrs.find('=', name_at);
      if (eq == std::string_view::npos) break;
      std::string_view key = attrs.substr(name_at, eq - name_at);
      key = key.substr(0, key.find_first_of(" \t\r\n"));
      const std::size_t quote = attrs.find_first_of("\"'", eq);
      if (quote == std::string_view::npos) break;
      const std::size_t value_end = attrs.find(attrs[quote], quote + 1);
      if (value_end == std::string_view::npos) break;
      if (key == attribute) return std::string(attrs.substr(quote + 1, value_end - quote - 1));
      i = value_end + 1;
    }
    return std::nullopt;
  }
  return std::nullopt;
}

}  // namespace selfsim::io
