#include "kernels/io/dataset/dataset_pipe.h"

#include "kernels/base/huge_pages.h"

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
  d.provenance.resize(static_cast<std::size_t>(get_count(in, 1u << 16)));
  in.read(d.provenance.data(), d.provenance.size());
  return d;
}

namespace {

template <class T>
void put_values(PipeOut& out, const std::vector<T>& values) {
  put_count(out, values.size());
  if (!values.empty()) out.write(values.data(), values.size() * sizeof(T));
}

void put_fields(PipeOut& out, const std::map<std::string, FieldValues>& fields) {
  put_count(out, fields.size());
  for (const auto& [name, f] : fields) {
    put_name(out, name);
    put_count(out, static_cast<std::uint64_t>(f.components));
    put_values(out, f.values);
  }
}

}  // namespace

void send_dataset(PipeOut& out, const Dataset& d) {
  put_count(out, static_cast<std::uint64_t>(d.shapes));
  put_values(out, d.points);
  std::vector<std::uint64_t> ids(d.cell_ends.begin(), d.cell_ends.end());
  put_values(out, ids);
  ids.assign(d.cell_points.begin(), d.cell_points.end());
  put_values(out, ids);
  put_fields(out, d.point_fields);
  put_fields(out, d.cell_fields);
  put_name(out, d.provenance.substr(0, 1u << 16));
}

}  // namespace selfsim::io
