// A Dataset sent from a reader child process to its parent (see child_process.h). The wire format, in
// native byte order (both ends are the same program on the same machine):
//   cell shapes:  a CellShapes value as a uint64
//   points:       count, then count x (x, y, z) doubles
//   cell ends:    count, then count uint64
//   cell points:  count, then count uint64
//   point fields, then cell fields: count, then per field: name length, name bytes, components,
//                 value count, then the values as doubles
//   provenance:   length, then its bytes (provenance.h; empty where the format holds none)
// where every count is a uint64. The child writes it straight from its reader's arrays, without building
// a Dataset of its own; the parent rebuilds the Dataset.
#pragma once

#include <cstdint>
#include <string>

#include "kernels/io/child_process.h"
#include "kernels/io/dataset/dataset.h"

namespace selfsim::io {

inline void put_count(PipeOut& out, std::uint64_t n) { out.write(&n, sizeof n); }
inline void put_name(PipeOut& out, const std::string& name) {
  put_count(out, name.size());
  out.write(name.data(), name.size());
}

// Sends a Dataset the child holds (a reader that builds one rather than writing from its own arrays).
void send_dataset(PipeOut& out, const Dataset& d);

// Refuses counts over max_values (the reader's memory budget in values) before allocating for them.
Dataset receive_dataset(PipeIn& in, std::uint64_t max_values);

// A reader child's whole answer: 'D' and the Dataset (send_success, then the dataset), or 'E' and a
// one-line reason (send_failure).
inline void send_success(PipeOut& out) { out.write("D", 1); }
void send_failure(PipeOut& out, const std::string& reason);
// The Dataset the child sent, or an Error with its reason; `reader` names the child for a malformed answer.
Dataset receive_answer(PipeIn& in, const std::string& reader, std::uint64_t max_values);

}  // namespace selfsim::io
