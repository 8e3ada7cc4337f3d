// The boundary/manifold check every mesh kernel's tests (and load()) use: is every edge shared by one or
// two faces, do neighbouring faces agree on orientation, what is the Euler characteristic, how many
// boundary loops and components are there.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "kernels/base/progress.h"
#include "kernels/geom/mesh.h"

namespace selfsim {

struct MeshTopology {
  std::size_t vertices = 0;              // points used by at least one triangle
  std::size_t edges = 0;                 // distinct undirected edges
  std::size_t faces = 0;                 // triangles
  std::size_t boundary_edges = 0;        // edges of exactly one face
  std::size_t boundary_loops = 0;        // chains of boundary edges (two touching at a bowtie count as one)
  std::size_t components = 0;            // face-connected pieces
  std::size_t nonmanifold_edges = 0;     // edges of three or more faces
  std::size_t misoriented_edges = 0;     // edges two faces traverse in the same direction
  std::size_t nonmanifold_vertices = 0;  // vertices whose faces form more than one fan (a bowtie)
  std::string first_problem;             // "edge (3, 7) is shared by 3 faces", empty when manifold

  // V - E + F: 2 for a sphere, 1 for a disk, 0 for an annulus or torus.
  long long euler() const {
    return static_cast<long long>(vertices) - static_cast<long long>(edges) + static_cast<long long>(faces);
  }
  // Every edge has one or two faces, consistently oriented, and every vertex is one fan of faces.
  bool manifold() const { return nonmanifold_edges == 0 && misoriented_edges == 0 && nonmanifold_vertices == 0; }
  // A manifold without boundary: a watertight, printable surface.
  bool closed() const { return manifold() && boundary_edges == 0 && faces > 0; }
};

// The first edge of m not shared by exactly two triangles running opposite ways, as a phrase for messages
// ("its edge from point 3 to point 7 (in triangle 2) has no other triangle"); empty when there is none.
// Points and triangles count from 1.
std::string first_open_edge(const Mesh& m);

// The topology of m. Points and faces in first_problem count from 1. O(F); looks for a stop (throws
// Cancelled) every 65,536 points and faces.
MeshTopology mesh_topology(const Mesh& m, Progress& progress = no_progress());

// Each face's face-connected piece (faces sharing an edge are in one), numbered from 0 in the order of each
// piece's first face. O(F).
std::vector<std::uint32_t> face_components(const Mesh& m, Progress& progress = no_progress());

}  // namespace selfsim
