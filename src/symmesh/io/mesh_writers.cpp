// .vtu, .msh 4.1 and .mesh writers, streamed from the templated mesh (spec/outputs.md#mesh-files).
#include "symmesh/io/mesh_writers.h"

#include "symmesh/io/atomic_file.h"

#include <zlib.h>

#include <algorithm>
#include <bit>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace symmesh::io {
namespace {

static_assert(std::endian::native == std::endian::little,
              "the binary writers declare little-endian data");

/// Numbers as text: the shortest form that reads back to the same double (std::to_chars).
template <class T>
void append_number(std::string& s, T v) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  s.append(buf, r.ptr);
}

/// Buffered output of one data array: text, raw bytes, or VTK zlib blocks. Values go in with
/// put(), rows end with end_row() (text only).
class ArrayWriter {
public:
  enum class Mode { text, raw, zlib };
  ArrayWriter(std::ostream& os, Mode mode) : os_(os), mode_(mode) {}

  /// Starts an array of `bytes` raw bytes (binary modes write its header here).
  void begin(std::uint64_t bytes) {
    bytes_ = bytes;
    if (mode_ == Mode::raw) {
      os_.write(reinterpret_cast<const char*>(&bytes), sizeof bytes);
    } else if (mode_ == Mode::zlib) {
      const std::uint64_t blocks = (bytes + kBlock - 1) / kBlock;
      compressed_sizes_.clear();
      header_at_ = os_.tellp();
      // [number of blocks, block size, last block size, compressed size of each block]; the
      // sizes are known only after compressing, so the header is written again at the end.
      const std::vector<std::uint64_t> zeros(3 + blocks, 0);
      os_.write(reinterpret_cast<const char*>(zeros.data()),
                std::streamsize(zeros.size() * sizeof(std::uint64_t)));
    }
  }
  template <class T>
  void put(T v) {
    if (mode_ == Mode::text) {
      append_number(buffer_, v);
      buffer_ += ' ';
      return; // flushed at the end of the row, whose last space becomes its newline
    }
    char b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));
    buffer_.append(b, sizeof(T));
    if (buffer_.size() >= kBlock) flush_binary(false);
  }
  void end_row() {
    if (mode_ != Mode::text) return;
    if (!buffer_.empty() && buffer_.back() == ' ') buffer_.back() = '\n';
    if (buffer_.size() >= kBlock) flush_text();
  }
  void end() {
    if (mode_ == Mode::text) {
      flush_text();
      return;
    }
    flush_binary(true);
    if (mode_ == Mode::zlib) {
      const auto end_at = os_.tellp();
      const std::uint64_t blocks = compressed_sizes_.size();
      const std::uint64_t last = bytes_ % kBlock == 0 ? (bytes_ ? kBlock : 0) : bytes_ % kBlock;
      std::vector<std::uint64_t> header{blocks, kBlock, last};
      header.insert(header.end(), compressed_sizes_.begin(), compressed_sizes_.end());
      os_.seekp(header_at_);
      os_.write(reinterpret_cast<const char*>(header.data()),
                std::streamsize(header.size() * sizeof(std::uint64_t)));
      os_.seekp(end_at);
    }
  }

  static constexpr std::uint64_t kBlock = 32768; ///< VTK's default compressor block size

private:
  void flush_text() {
    os_.write(buffer_.data(), std::streamsize(buffer_.size()));
    buffer_.clear();
  }
  void flush_binary(bool last) {
    if (mode_ == Mode::raw) {
      os_.write(buffer_.data(), std::streamsize(buffer_.size()));
      buffer_.clear();
      return;
    }
    std::size_t at = 0;
    while (buffer_.size() - at >= kBlock || (last && at < buffer_.size())) {
      const std::size_t n = std::min<std::size_t>(kBlock, buffer_.size() - at);
      uLongf size = compressBound(uLong(n));
      compressed_.resize(size);
      if (compress2(reinterpret_cast<Bytef*>(compressed_.data()), &size,
                    reinterpret_cast<const Bytef*>(buffer_.data() + at), uLong(n),
                    Z_DEFAULT_COMPRESSION) != Z_OK)
        throw std::runtime_error("zlib compression failed");
      os_.write(compressed_.data(), std::streamsize(size));
      compressed_sizes_.push_back(size);
      at += n;
    }
    buffer_.erase(0, at);
  }

  std::ostream& os_;
  Mode mode_;
  std::string buffer_, compressed_;
  std::uint64_t bytes_ = 0;
  std::streampos header_at_{};
  std::vector<std::uint64_t> compressed_sizes_;
};

/// Calls f(instance, template, region, cell type) for every cell of AT in order, without the
/// vertex numbering (cell data need none).
template <class F>
void for_each_cell_record(const mesh::StructureInstance& at, F&& f) {
  std::size_t k = 0;
  const auto& templates = at.templated().templated.templates;
  for (std::size_t i = 0; i < templates.size(); ++i)
    for (std::size_t g = 0; g < templates[i].instance_count(); ++g, ++k)
      for (auto type : templates[i].mesh.cell_types) f(k, i, templates[i].region_ids[g], type);
}

/// One progress stage over AT's vertices and cells, updated every 2^16 items.
struct WriteProgress {
  mesh::Progress* p;
  std::size_t done = 0;
  WriteProgress(mesh::Progress* progress, const mesh::StructureInstance& at,
                const std::string& path)
      : p(progress) {
    if (p) p->stage("writing " + path, at.vertex_count() + at.cell_count(), "vertices + cells");
  }
  void tick() {
    if (p && (++done & 0xffff) == 0) p->set_done(done);
  }
};

struct VtuArray {
  std::string name, type;
  int components = 1, value_bytes = 0;
  std::uint64_t values = 0;
  std::uint64_t bytes() const { return values * std::uint64_t(value_bytes); }
};

} // namespace

void write_vtu(const mesh::StructureInstance& at, const std::string& path,
               const MeshFileOptions& o) {
  const int dim = at.dimension();
  const std::size_t nv = at.vertex_count(), nc = at.cell_count();
  std::uint64_t indices = 0;
  for_each_cell_record(at, [&](auto, auto, auto, mesh::ElementType t) {
    indices += std::uint64_t(mesh::vertex_count(t));
  });
  const bool wide_offsets = indices > std::uint64_t(std::numeric_limits<std::int32_t>::max());
  std::vector<VtuArray> arrays{
      {"", "Float64", 3, 8, 3 * std::uint64_t(nv)},
      {"connectivity", "Int32", 1, 4, indices},
      {"offsets", wide_offsets ? "Int64" : "Int32", 1, wide_offsets ? 8 : 4, nc},
      {"types", "UInt8", 1, 1, nc},
      {"region", "Int32", 1, 4, nc},
      {"template", "Int32", 1, 4, nc},
      {"instance", "Int32", 1, 4, nc}};
  constexpr std::size_t first_point_data = 7;
  for (const auto& [name, v] : o.point_data) {
    if (!v || v->size() != nv)
      throw std::logic_error("write_vtu: point data '" + name + "' has the wrong size");
    arrays.push_back({name, "Float64", 1, 8, nv});
  }
  const auto point_data_xml = [&](const auto& tag_of) {
    if (o.point_data.empty()) return std::string();
    std::string h = "<PointData Scalars=\"" + o.point_data[0].first + "\">\n";
    for (std::size_t a = first_point_data; a < arrays.size(); ++a) h += tag_of(a);
    return h + "</PointData>\n";
  };
  const auto mode = o.ascii      ? ArrayWriter::Mode::text
                    : o.compress ? ArrayWriter::Mode::zlib
                                 : ArrayWriter::Mode::raw;
  WriteProgress progress(o.progress, at, path);
  // Compressed sizes are known only after compressing, and readers look arrays up by their exact
  // offset, so compressed data go to a side file first and are copied behind the header.
  const std::string side_path = path + ".data.part";
  struct RemoveSide {
    const std::string& p;
    ~RemoveSide() {
      std::error_code ec;
      std::filesystem::remove(p, ec);
    }
  } remove_side{side_path};
  std::fstream side;
  if (mode == ArrayWriter::Mode::zlib) {
    side.open(side_path, std::ios::binary | std::ios::in | std::ios::out | std::ios::trunc);
    if (!side) throw std::runtime_error(path + ": cannot write");
  }
  write_atomically(path, [&](std::ostream& os) {
    std::vector<std::string> offset_text;
    std::uint64_t offset = 0;
    for (const auto& a : arrays) {
      offset_text.push_back(std::to_string(offset));
      offset += 8 + a.bytes();
    }
    std::string head =
        "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" "
        "byte_order=\"LittleEndian\" header_type=\"UInt64\"";
    if (mode == ArrayWriter::Mode::zlib) head += " compressor=\"vtkZLibDataCompressor\"";
    head += ">\n<UnstructuredGrid>\n<Piece NumberOfPoints=\"" + std::to_string(nv) +
            "\" NumberOfCells=\"" + std::to_string(nc) + "\">\n";
    const auto tag = [&](std::size_t a) {
      const auto& d = arrays[a];
      std::string t = "<DataArray type=\"" + d.type + "\"";
      if (!d.name.empty()) t += " Name=\"" + d.name + "\"";
      if (d.components != 1) t += " NumberOfComponents=\"" + std::to_string(d.components) + "\"";
      if (mode == ArrayWriter::Mode::text) return t + " format=\"ascii\">\n";
      return t + " format=\"appended\" offset=\"" + offset_text[a] + "\"/>\n";
    };
    // The arrays' values, in file order.
    std::ostream& data = mode == ArrayWriter::Mode::zlib ? static_cast<std::ostream&>(side) : os;
    ArrayWriter w(data, mode);
    const auto values = [&](std::size_t a) {
      w.begin(arrays[a].bytes());
      switch (a) {
      case 0:
        at.for_each_vertex([&](const double* x) {
          w.put(x[0]);
          w.put(x[1]);
          w.put(dim == 3 ? x[2] : 0.0);
          w.end_row();
          progress.tick();
        });
        break;
      case 1:
        at.for_each_cell(
            [&](const auto& in, std::size_t c, const std::array<mesh::IndexType, 4>& v) {
              const int n = mesh::vertex_count(in.mesh_template->mesh.cell_types[c]);
              for (int q = 0; q < n; ++q) w.put(std::int32_t(v[std::size_t(q)]));
              w.end_row();
              progress.tick();
            });
        break;
      case 2: {
        std::uint64_t end = 0;
        for_each_cell_record(at, [&](auto, auto, auto, mesh::ElementType t) {
          end += std::uint64_t(mesh::vertex_count(t));
          if (wide_offsets)
            w.put(std::int64_t(end));
          else
            w.put(std::int32_t(end));
          w.end_row();
        });
        break;
      }
      case 3:
        for_each_cell_record(at, [&](auto, auto, auto, mesh::ElementType t) {
          w.put(std::uint8_t(t));
          w.end_row();
        });
        break;
      default:
        if (a >= first_point_data) {
          for (double v : *o.point_data[a - first_point_data].second) {
            w.put(v);
            w.end_row();
          }
          break;
        }
        for_each_cell_record(at, [&](std::size_t k, std::size_t i, mesh::RegionIdType r, auto) {
          w.put(std::int32_t(a == 4 ? int(r) : a == 5 ? int(i) + 1 : int(k) + 1));
          w.end_row();
        });
      }
      w.end();
    };
    if (mode == ArrayWriter::Mode::text) {
      // ASCII: the values sit inside their DataArray elements.
      const auto inline_array = [&](std::size_t a) {
        os << tag(a);
        values(a);
        os << "</DataArray>\n";
      };
      os << head << "<Points>\n";
      inline_array(0);
      os << "</Points>\n<Cells>\n";
      for (std::size_t a = 1; a <= 3; ++a) inline_array(a);
      os << "</Cells>\n<CellData Scalars=\"region\">\n";
      for (std::size_t a = 4; a < first_point_data; ++a) inline_array(a);
      os << "</CellData>\n";
      if (!o.point_data.empty()) {
        os << "<PointData Scalars=\"" << o.point_data[0].first << "\">\n";
        for (std::size_t a = first_point_data; a < arrays.size(); ++a) inline_array(a);
        os << "</PointData>\n";
      }
      os << "</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
      return;
    }
    const auto appended_head = [&] {
      std::string h = head + "<Points>\n" + tag(0) + "</Points>\n<Cells>\n";
      for (std::size_t a = 1; a <= 3; ++a) h += tag(a);
      h += "</Cells>\n<CellData Scalars=\"region\">\n";
      for (std::size_t a = 4; a < first_point_data; ++a) h += tag(a);
      h += "</CellData>\n" + point_data_xml(tag);
      return h + "</Piece>\n</UnstructuredGrid>\n<AppendedData encoding=\"raw\">\n_";
    };
    if (mode == ArrayWriter::Mode::raw) os << appended_head();
    const auto data_start = data.tellp();
    for (std::size_t a = 0; a < arrays.size(); ++a) {
      const std::string at_text = std::to_string(std::uint64_t(data.tellp() - data_start));
      if (mode == ArrayWriter::Mode::zlib)
        offset_text[a] = at_text;
      else if (at_text != offset_text[a])
        throw std::logic_error("write_vtu: appended offsets do not match the array sizes");
      values(a);
    }
    if (mode == ArrayWriter::Mode::zlib) {
      data.flush();
      if (!data) throw std::runtime_error(path + ": cannot write");
      os << appended_head();
      side.seekg(0);
      os << side.rdbuf();
    }
    os << "\n</AppendedData>\n</VTKFile>\n";
  });
  if (o.progress) o.progress->set_done(nv + nc);
}

namespace {

/// MSH 4.1 values: text separated by spaces, or binary (size_t 8 bytes, int 4, double 8).
class MshWriter {
public:
  MshWriter(std::ostream& os, bool ascii) : os_(os), ascii_(ascii) {}
  void size(std::uint64_t v) { put(v); }
  void integer(std::int32_t v) { put(v); }
  void real(double v) { put(v); }
  void end_row() {
    if (!ascii_) return;
    if (!buffer_.empty() && buffer_.back() == ' ') buffer_.back() = '\n';
    if (buffer_.size() >= (1u << 16)) flush();
  }
  /// Ends a section's data and writes the closing keyword.
  void close(const char* keyword) {
    if (!ascii_) buffer_ += '\n';
    buffer_ += keyword;
    buffer_ += '\n';
    flush();
  }
  void text(const std::string& s) { buffer_ += s; }
  void flush() {
    os_.write(buffer_.data(), std::streamsize(buffer_.size()));
    buffer_.clear();
  }

private:
  template <class T>
  void put(T v) {
    if (ascii_) {
      append_number(buffer_, v);
      buffer_ += ' ';
    } else {
      char b[sizeof(T)];
      std::memcpy(b, &v, sizeof(T));
      buffer_.append(b, sizeof(T));
    }
    if (!ascii_ && buffer_.size() >= (1u << 16)) flush(); // text: at the end of the row
  }
  std::ostream& os_;
  bool ascii_;
  std::string buffer_;
};

} // namespace

void write_msh41(const mesh::StructureInstance& at, const std::string& path,
                 const MeshFileOptions& o) {
  const int dim = at.dimension();
  const std::size_t nv = at.vertex_count(), nc = at.cell_count();
  std::map<int, std::size_t> cells_of_region;
  int gmsh_type = dim == 2 ? 2 : 4; // 3-node triangle, 4-node tetrahedron
  for_each_cell_record(at, [&](auto, auto, mesh::RegionIdType r, mesh::ElementType t) {
    cells_of_region[int(r)]++;
    gmsh_type = t == mesh::ElementType::triangle ? 2 : 4;
  });
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  bool first = true;
  at.for_each_vertex([&](const double* x) {
    for (int d = 0; d < 3; ++d) {
      const double c = d < dim ? x[d] : 0.0;
      if (first || c < lo[d]) lo[d] = c;
      if (first || c > hi[d]) hi[d] = c;
    }
    first = false;
  });
  WriteProgress progress(o.progress, at, path);
  write_atomically(path, [&](std::ostream& os) {
    MshWriter w(os, o.ascii);
    w.text(o.ascii ? "$MeshFormat\n4.1 0 8\n" : "$MeshFormat\n4.1 1 8\n");
    if (!o.ascii) w.integer(1); // lets a reader detect the byte order
    w.close("$EndMeshFormat");
    // Physical names are text in both encodings.
    w.text("$PhysicalNames\n" + std::to_string(cells_of_region.size()) + "\n");
    for (const auto& [region, cells] : cells_of_region)
      w.text(std::to_string(dim) + " " + std::to_string(region) + " \"region_" +
             std::to_string(region) + "\"\n");
    w.text("$EndPhysicalNames\n$Entities\n");
    for (int d = 0; d <= 3; ++d) w.size(d == dim ? cells_of_region.size() : 0);
    w.end_row();
    for (const auto& [region, cells] : cells_of_region) {
      w.integer(region);
      for (int d = 0; d < 3; ++d) w.real(lo[d]);
      for (int d = 0; d < 3; ++d) w.real(hi[d]);
      w.size(1);
      w.integer(region);
      w.size(0); // no bounding entities
      w.end_row();
    }
    w.close("$EndEntities");
    w.text("$Nodes\n");
    const int first_entity = cells_of_region.empty() ? 1 : cells_of_region.begin()->first;
    for (std::uint64_t v :
         {std::uint64_t(1), std::uint64_t(nv), std::uint64_t(1), std::uint64_t(nv)})
      w.size(v);
    w.end_row();
    w.integer(dim);
    w.integer(first_entity);
    w.integer(0);
    w.size(nv);
    w.end_row();
    for (std::size_t v = 0; v < nv; ++v) {
      w.size(v + 1);
      w.end_row();
    }
    at.for_each_vertex([&](const double* x) {
      for (int d = 0; d < 3; ++d) w.real(d < dim ? x[d] : 0.0);
      w.end_row();
      progress.tick();
    });
    w.close("$EndNodes");
    w.text("$Elements\n");
    for (std::uint64_t v : {std::uint64_t(cells_of_region.size()), std::uint64_t(nc),
                            std::uint64_t(1), std::uint64_t(nc)})
      w.size(v);
    w.end_row();
    std::uint64_t tag = 1;
    for (const auto& [region, count] : cells_of_region) {
      w.integer(dim);
      w.integer(region);
      w.integer(gmsh_type);
      w.size(count);
      w.end_row();
      const int block = region; // a structured binding cannot be captured before clang 16
      at.for_each_cell([&](const auto& in, std::size_t c, const std::array<mesh::IndexType, 4>& v) {
        if (int(in.region) != block) return;
        w.size(tag++);
        for (int q = 0; q < mesh::vertex_count(in.mesh_template->mesh.cell_types[c]); ++q)
          w.size(std::uint64_t(v[std::size_t(q)]) + 1);
        w.end_row();
        progress.tick();
      });
    }
    w.close("$EndElements");
  });
}

void write_medit(const mesh::StructureInstance& at, const std::string& path,
                 const MeshFileOptions& o) {
  const int dim = at.dimension();
  WriteProgress progress(o.progress, at, path);
  write_atomically(path, [&](std::ostream& os) {
    std::string b = "MeshVersionFormatted 2\nDimension " + std::to_string(dim) + "\nVertices\n" +
                    std::to_string(at.vertex_count()) + "\n";
    const auto flush = [&] {
      if (b.size() >= (1u << 16)) {
        os.write(b.data(), std::streamsize(b.size()));
        b.clear();
      }
    };
    at.for_each_vertex([&](const double* x) {
      for (int d = 0; d < dim; ++d) {
        append_number(b, x[d]);
        b += ' ';
      }
      b += "0\n";
      flush();
      progress.tick();
    });
    b += dim == 2 ? "Triangles\n" : "Tetrahedra\n";
    b += std::to_string(at.cell_count()) + "\n";
    at.for_each_cell([&](const auto& in, std::size_t c, const std::array<mesh::IndexType, 4>& v) {
      for (int q = 0; q < mesh::vertex_count(in.mesh_template->mesh.cell_types[c]); ++q) {
        append_number(b, v[std::size_t(q)] + 1);
        b += ' ';
      }
      append_number(b, int(in.region));
      b += '\n';
      flush();
      progress.tick();
    });
    b += "End\n";
    os.write(b.data(), std::streamsize(b.size()));
  });
}

void write_mesh_file(const mesh::StructureInstance& at, const std::string& path,
                     const MeshFileOptions& o) {
  const std::string ext = std::filesystem::path(path).extension().string();
  if (o.compress && ext != ".vtu")
    throw std::invalid_argument(path + ": --compress applies to .vtu only");
  if (ext == ".vtu") return write_vtu(at, path, o);
  if (ext == ".msh") return write_msh41(at, path, o);
  if (ext == ".mesh") return write_medit(at, path, o);
  throw std::invalid_argument(path + ": unknown mesh file extension '" + ext +
                              "' (use .vtu, .msh or .mesh)");
}

} // namespace symmesh::io
