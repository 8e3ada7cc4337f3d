#include "kernels/io/dataset_pipe.h"

#include "kernels/geom/huge_pages.h"

namespace selfsim::io {

namespace {

std::uint64_t get_count(PipeIn& in, std::uint64_t max) {
  std::uint64_t n = 0;
  in.read(&n, sizeof n);
  if (n > max)
    throw Error("the reader process sent a count of " + std::to_string(n) + ", over the limit of " +
                std::to_string(max));
  return n;
}

template <class T>
void get_values(PipeIn& in, std::vector<T>& v, std::uint64_t max) {
  const std::uint64_t n = get_count(in, max);
  v.reserve(static_cast<std::size_t>(n));
  advise_huge_pages(v);  // first touch of a large array costs far less in 2 MiB pages
  v.resize(static_cast<std::size_t>(n));
  in.read(v.data(), v.size() * sizeof(T));
}

void get_fields(PipeIn& in, std::map<std::string, FieldValues>& fields, std::uint64_t max_values) {
  const std::uint64_t count = get_count(in, 1u << 16);
  for (std::uint64_t i = 0; i < count; ++i) {
    std::string name(static_cast<std::size_t>(get_count(in, 1u << 16)), '\0');
    in.read(name.data(), name.size());
    FieldValues f;
    f.components = static_cast<int>(get_count(in, 1u << 16));
    get_values(in, f.values, max_values);
    fields[name] = std::move(f);
  }
}

}  // namespace

void send_failure(PipeOut& out, const std::string& reason) {
  out.write("E", 1);
  put_name(out, reason.substr(0, 4096));
}

Dataset receive_answer(PipeIn& in, const std::string& reader, std::uint64_t max_values) {
  char kind = 0;
  in.read(&kind, 1);
  if (kind == 'E') {
    std::string reason(static_cast<std::size_t>(get_count(in, 4096)), '\0');
    in.read(reason.data(), reason.size());
    throw Error(reason);
  }
  if (kind != 'D') throw Error(reader + " sent a malformed answer");
  return receive_dataset(in, max_values);
}

Dataset receive_dataset(PipeIn& in, std::uint64_t max_values) {
  Dataset d;
  d.shapes = static_cast<CellShapes>(get_count(in, 2));
  get_values(in, d.points, max_values / 3);
  get_values(in, d.cell_ends, max_values);
  get_values(in, d.cell_points, max_values);
  get_fields(in, d.point_fields, max_values);
  get_fields(in, d.cell_fields, max_values);
  return d;
}

}  // namespace selfsim::io
