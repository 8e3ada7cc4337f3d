// OpenVDB's part of reading .vdb files (see vdb_read.h). Only the file reader and volumeToMesh: a small
// translation unit next to level_set.cpp, which holds the writing side.
#include "kernels/io/vdb/vdb_read.h"

#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>
#include <openvdb/tools/VolumeToMesh.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <mutex>

#include "kernels/base/check.h"
#include "kernels/base/error.h"
#include "kernels/io/child_process.h"
#include "kernels/io/dataset/dataset_pipe.h"
#include "kernels/io/read_error.h"
#include "kernels/io/regular_file.h"
#include "kernels/plugins/openvdb/vdb_grid_checks.h"

namespace selfsim::io {

namespace {

// In a forked child: OpenVDB's registries, and TBB on this thread alone.
struct ChildSetup {
  ChildSetup() : one_thread(tbb::global_control::max_allowed_parallelism, 1) {
    static std::once_flag once;
    std::call_once(once, [] { openvdb::initialize(); });
  }
  tbb::global_control one_thread;
};

std::string class_name(openvdb::GridClass c) {
  switch (c) {
    case openvdb::GRID_LEVEL_SET:
      return "level set";
    case openvdb::GRID_FOG_VOLUME:
      return "fog volume";
    case openvdb::GRID_STAGGERED:
      return "staggered";
    default:
      return "unknown";
  }
}

void put_double(PipeOut& out, double v) { out.write(&v, sizeof v); }
double get_double(PipeIn& in) {
  double v = 0;
  in.read(&v, sizeof v);
  return v;
}
std::uint64_t get_count(PipeIn& in, std::uint64_t max) {
  std::uint64_t n = 0;
  in.read(&n, sizeof n);
  if (n > max) throw Error("the OpenVDB reader sent a malformed answer");
  return n;
}
std::string get_name(PipeIn& in) {
  std::string s(static_cast<std::size_t>(get_count(in, 1 << 16)), '\0');
  in.read(s.data(), s.size());
  return s;
}

// 'E' and a reason, or what `answer` sends after 'D' (given the file's size, which bounds its leaves).
template <class Answer>
int in_child(PipeOut& out, const std::string& name, std::uint64_t file_bytes, Answer answer) {
  try {
    ChildSetup setup;
    openvdb::io::File file(name);
    file.open(false);  // read into memory, no delayed loading from a mapped file
    answer(out, file, file_bytes);
  } catch (const std::bad_alloc&) {
    send_failure(out, "out of memory");
  } catch (const std::exception& e) {
    send_failure(out, e.what());
  }
  return 0;
}

// Runs `answer` on the opened file in a child, and `receive` on its answer after 'D'. `metadata_only`: the
// child reads no voxels, so it may use little more memory than the file holds (a crafted string length
// otherwise had OpenVDB zero gigabytes for 10 s before it failed, found by fuzzing).
template <class Answer, class Receive>
void read_in_child(const std::filesystem::path& file, Answer answer, Receive receive, bool metadata_only) {
  const RegularFile f(file);
  if (f.size() > read_budget_bytes() / 8)
    throw Error("the file is " + std::to_string(f.size() >> 20) + " MiB, over the reading limit of " +
                std::to_string(read_budget_bytes() / 8 >> 20) + " MiB for .vdb files");
  const std::string name = f.reopen_name(file);
  ChildLimits limits;
  limits.what = "the OpenVDB reader";
  limits.memory_bytes =
      (std::uint64_t{1} << 30) +
      (metadata_only ? std::min<std::uint64_t>(64 * f.size(), read_budget_bytes()) : read_budget_bytes());
  // Metadata takes milliseconds; a crafted count can keep OpenVDB looping over an ended stream instead.
  limits.seconds = (metadata_only ? 3 : 30) + static_cast<double>(f.size()) / (4 << 20);
  run_in_child(
      limits, [&](PipeOut& out) { return in_child(out, name, f.size(), answer); },
      [&](PipeIn& in) {
        char kind = 0;
        in.read(&kind, 1);
        if (kind == 'E') throw Error(get_name(in).substr(0, 4096));
        if (kind != 'D') throw Error("the OpenVDB reader sent a malformed answer");
        receive(in);
      });
}

template <class Read>
auto reading(const std::filesystem::path& file, Read read) {
  try {
    return read();
  } catch (const std::bad_alloc&) {
    throw Error(cannot_read(file, "out of memory"));
  } catch (const BudgetError&) {  // names the file itself; the run may collect garbage and try again
    throw;
  } catch (const std::exception& e) {
    const std::string message = e.what();
    if (message.rfind("cannot read '", 0) == 0) throw;
    throw Error(cannot_read(file, message));
  }
}

void send_info(PipeOut& out, openvdb::io::File& file, std::uint64_t /*file_bytes*/) {
  const openvdb::GridPtrVecPtr grids = file.readAllGridMetadata();
  out.write("D", 1);
  put_count(out, grids ? grids->size() : 0);
  if (!grids) return;
  for (const openvdb::GridBase::Ptr& g : *grids) {
    put_name(out, g->getName());
    put_name(out, class_name(g->getGridClass()));
    put_name(out, g->valueType());
    const openvdb::Vec3d voxel = g->voxelSize();
    for (int k = 0; k < 3; ++k) put_double(out, voxel[k]);
    put_count(out, meta_count(*g, openvdb::GridBase::META_FILE_VOXEL_COUNT));
    const auto lo = g->getMetadata<openvdb::Vec3IMetadata>(openvdb::GridBase::META_FILE_BBOX_MIN);
    const auto hi = g->getMetadata<openvdb::Vec3IMetadata>(openvdb::GridBase::META_FILE_BBOX_MAX);
    const bool has = lo && hi && lo->value().x() <= hi->value().x();
    out.write(has ? "1" : "0", 1);
    if (!has) continue;
    double wlo[3], whi[3];
    for (int corner = 0; corner < 8; ++corner) {
      const openvdb::Vec3d index((corner & 1 ? hi : lo)->value().x(), (corner & 2 ? hi : lo)->value().y(),
                                 (corner & 4 ? hi : lo)->value().z());
      const openvdb::Vec3d w = g->transform().indexToWorld(index);
      for (int k = 0; k < 3; ++k) {
        wlo[k] = corner == 0 ? w[k] : std::min(wlo[k], w[k]);
        whi[k] = corner == 0 ? w[k] : std::max(whi[k], w[k]);
      }
    }
    for (int k = 0; k < 3; ++k) put_count(out, static_cast<std::uint64_t>(static_cast<std::int64_t>(lo->value()[k])));
    for (int k = 0; k < 3; ++k) put_count(out, static_cast<std::uint64_t>(static_cast<std::int64_t>(hi->value()[k])));
    for (int k = 0; k < 3; ++k) put_double(out, wlo[k]);
    for (int k = 0; k < 3; ++k) put_double(out, whi[k]);
  }
}

// Chooses the grid (see vdb_read.h), reads it, checks it, sends its description and what its tiles weigh
// (the parent refuses them here, before any meshing), then meshes it and sends the Dataset and, with
// `samples`, its voxels.
void send_surface(PipeOut& out, openvdb::io::File& file, std::uint64_t file_bytes, const std::string& wanted,
                  bool samples) {
  const openvdb::GridPtrVecPtr grids = file.readAllGridMetadata();
  openvdb::GridBase::Ptr chosen;
  if (grids && !wanted.empty()) {
    std::string names;
    for (const openvdb::GridBase::Ptr& g : *grids) {
      if (g->getName() == wanted) chosen = g;
      names += (names.empty() ? "'" : ", '") + shown(g->getName()) + "'";
    }
    if (!chosen) throw Error("it holds no grid named '" + shown(wanted) + "' (its grids: " + names + ")");
    if (!chosen->isType<openvdb::FloatGrid>())
      throw Error("grid '" + shown(wanted) + "' holds " + chosen->valueType() + " values, not a float level set");
  }
  if (grids)
    for (bool level_set : {true, false})
      for (const openvdb::GridBase::Ptr& g : *grids)
        if (!chosen && g->isType<openvdb::FloatGrid>() && (!level_set || g->getGridClass() == openvdb::GRID_LEVEL_SET))
          chosen = g;
  if (!chosen) throw Error("it holds no float grid (a level set or a fog volume) to draw a surface of");
  check_declared_memory(*chosen, file_bytes);  // before reading any voxel
  const openvdb::FloatGrid::Ptr grid = openvdb::gridPtrCast<openvdb::FloatGrid>(file.readGrid(chosen->getName()));
  if (!grid) throw Error("grid '" + shown(chosen->getName()) + "' is not a float grid");
  const openvdb::GridClass c = grid->getGridClass();
  double iso = 0;
  std::string what = class_name(c) + " '" + grid->getName() + "'";
  if (c == openvdb::GRID_FOG_VOLUME) {
    iso = 0.5;
    what += " at density 0.5";
  } else if (c != openvdb::GRID_LEVEL_SET) {
    bool negative = false;
    for (auto v = grid->cbeginValueOn(); v && !negative; ++v) negative = *v < 0;
    if (!negative) {  // an unsigned distance: no inside, so a thin shell around the surface
      iso = 0.5 * grid->voxelSize()[0];
      what += " (no negative values: drawn at half a voxel, " + number_text(iso) + ")";
    } else {
      what += " at 0";
    }
  } else {
    what += " at 0";
  }
  check_grid(*grid, c == openvdb::GRID_FOG_VOLUME);
  const Tiles tiles = active_tiles(*grid, iso);
  // A level set's own voxels (GridSamples) when asked, and when its transform is a uniform scale and
  // translation.
  const auto map = grid->transform().mapType();
  const bool uniform =
      map == openvdb::math::UniformScaleMap::mapType() || map == openvdb::math::UniformScaleTranslateMap::mapType();
  samples = samples && c == openvdb::GRID_LEVEL_SET && uniform && grid->background() > 0;
  out.write("D", 1);
  put_name(out, grid->getName());
  put_name(out, what);
  put_count(out, tiles.count);
  put_double(out, tiles.surface);
  put_double(out, samples ? active_voxels(*grid) : 0.0);
  out.flush();  // the parent weighs these while the mesh is made, and ends this process if they do not fit
  std::vector<openvdb::Vec3s> points;
  std::vector<openvdb::Vec3I> triangles;
  std::vector<openvdb::Vec4I> quads;
  openvdb::tools::volumeToMesh(*grid, points, triangles, quads, iso, 0.0);
  // After the header a second 'D', or 'E' and the reason (in_child sends it for what is thrown here).
  if (points.empty()) throw Error("grid '" + shown(grid->getName()) + "' has no surface at " + number_text(iso));
  out.write("D", 1);
  // The Dataset in dataset_pipe.h's wire format: polygons, points, cell ends, cell points, no fields.
  put_count(out, static_cast<std::uint64_t>(CellShapes::polygons));
  put_count(out, points.size());
  for (const openvdb::Vec3s& p : points)
    for (int k = 0; k < 3; ++k) put_double(out, p[k]);
  put_count(out, triangles.size() + quads.size());
  std::uint64_t end = 0;
  for (std::size_t i = 0; i < triangles.size(); ++i) put_count(out, end += 3);
  for (std::size_t i = 0; i < quads.size(); ++i) put_count(out, end += 4);
  put_count(out, end);
  for (const openvdb::Vec3I& t : triangles)
    for (int k = 0; k < 3; ++k) put_count(out, t[k]);
  for (const openvdb::Vec4I& q : quads)
    for (int k = 0; k < 4; ++k) put_count(out, q[k]);
  put_count(out, 0);
  put_count(out, 0);
  put_name(out, "");  // no provenance inside: a .vdb carries it beside it (provenance.h)
  if (!samples) return;
  // The voxel, origin and background, then each active value once: a voxel or a whole tile, as its lowest
  // corner, its width (1 for a voxel) and its value. The parent expands the tiles into the count announced.
  put_double(out, grid->voxelSize()[0]);
  const openvdb::Vec3d origin = grid->indexToWorld(openvdb::Vec3d(0, 0, 0));
  for (int k = 0; k < 3; ++k) put_double(out, origin[k]);
  put_double(out, grid->background());
  for (auto v = grid->cbeginValueOn(); v; ++v) {
    openvdb::CoordBBox box;
    v.getBoundingBox(box);
    for (int k = 0; k < 3; ++k) put_count(out, static_cast<std::uint64_t>(static_cast<std::int64_t>(box.min()[k])));
    put_count(out, static_cast<std::uint64_t>(box.dim().x()));
    put_double(out, *v);
  }
}

// What send_surface sent after the surface: `voxels` voxels (0: none sent), each checked finite and in
// range, a tile's expanded into one sample per voxel.
GridSamples receive_samples(PipeIn& in, std::uint64_t voxels) {
  GridSamples g;
  if (voxels == 0) return g;
  g.voxel = get_double(in);
  g.origin = {get_double(in), get_double(in), get_double(in)};
  g.background = get_double(in);
  if (!(g.voxel > 0 && std::isfinite(g.voxel) && is_finite(g.origin) && g.background > 0 &&
        std::isfinite(g.background)))
    throw Error("the OpenVDB reader sent a malformed answer");
  g.index.reserve(voxels);
  g.value.reserve(voxels);
  while (g.index.size() < voxels) {
    std::int64_t lo[3];
    for (std::int64_t& x : lo) x = static_cast<std::int64_t>(get_count(in, ~std::uint64_t{0}));
    const std::uint64_t side = get_count(in, 4096);  // the widest tile of a float grid: the root's, 4096
    const double v = get_double(in);
    if (!std::isfinite(v)) throw Error("grid values that are not finite");
    if (side == 0 || side * side * side > voxels - g.index.size())
      throw Error("the OpenVDB reader sent more voxels than it announced");
    for (const std::int64_t x : lo)
      if (x < -2147483647 || x + static_cast<std::int64_t>(side) > 2147483647)
        throw Error("the OpenVDB reader sent a malformed answer");
    const auto n = static_cast<std::int32_t>(side);
    for (std::int32_t i = 0; i < n; ++i)
      for (std::int32_t j = 0; j < n; ++j)
        for (std::int32_t k = 0; k < n; ++k) {
          g.index.push_back({static_cast<std::int32_t>(lo[0] + i), static_cast<std::int32_t>(lo[1] + j),
                             static_cast<std::int32_t>(lo[2] + k)});
          g.value.push_back(static_cast<float>(v));
        }
  }
  return g;
}

// What send_info sent.
std::vector<VdbGridInfo> receive_info(PipeIn& in) {
  std::vector<VdbGridInfo> grids;
  const std::uint64_t n = get_count(in, 1 << 16);
  for (std::uint64_t i = 0; i < n; ++i) {
    VdbGridInfo g;
    g.name = get_name(in);
    g.grid_class = get_name(in);
    g.value_type = get_name(in);
    for (double& v : g.voxel) v = get_double(in);
    g.active_voxels = get_count(in, ~std::uint64_t{0});
    char has = 0;
    in.read(&has, 1);
    g.has_bbox = has == '1';
    if (g.has_bbox) {
      for (auto& v : g.index_min) v = static_cast<std::int64_t>(get_count(in, ~std::uint64_t{0}));
      for (auto& v : g.index_max) v = static_cast<std::int64_t>(get_count(in, ~std::uint64_t{0}));
      for (double& v : g.world_min) v = get_double(in);
      for (double& v : g.world_max) v = get_double(in);
    }
    grids.push_back(std::move(g));
  }
  return grids;
}

}  // namespace

std::vector<VdbGridInfo> read_vdb_info(const std::filesystem::path& file) {
  return reading(file, [&] {
    std::vector<VdbGridInfo> grids;
    read_in_child(
        file, send_info, [&](PipeIn& in) { grids = receive_info(in); }, true);
    return grids;
  });
}

VdbSurface read_vdb_surface(const std::filesystem::path& file, const VdbReadOptions& opt) {
  const std::filesystem::path named = opt.shown_as.empty() ? file : opt.shown_as;
  return reading(named, [&] {
    VdbSurface s;
    // The metadata first, under the metadata's memory limit, before a child that may read voxels.
    read_in_child(
        file, send_info, [](PipeIn& in) { receive_info(in); }, true);
    const auto answer = [&](PipeOut& out, openvdb::io::File& f, std::uint64_t bytes) {
      send_surface(out, f, bytes, opt.grid, opt.samples);
    };
    read_in_child(
        file, answer,
        [&](PipeIn& in) {
          s.grid = get_name(in);
          s.what = get_name(in);
          Tiles tiles;
          tiles.count = get_count(in, ~std::uint64_t{0});
          tiles.surface = get_double(in);
          const double voxels = get_double(in);
          weigh(s, named, opt, tiles, voxels);
          char kind = 0;  // the mesh, or why there is none
          in.read(&kind, 1);
          if (kind == 'E') throw Error(get_name(in).substr(0, 4096));
          if (kind != 'D') throw Error("the OpenVDB reader sent a malformed answer");
          s.mesh = receive_dataset(in, read_budget_bytes() / 8);
          s.samples = receive_samples(in, static_cast<std::uint64_t>(voxels));
        },
        false);
    const Dataset& d = s.mesh;
    if (d.cell_ends.empty() || d.cell_ends.back() != d.cell_points.size())
      throw Error("the OpenVDB reader sent a malformed answer");
    for (std::size_t p : d.cell_points)
      if (p >= d.points.size()) throw Error("OpenVDB made a polygon with a point out of range");
    return s;
  });
}

}  // namespace selfsim::io
