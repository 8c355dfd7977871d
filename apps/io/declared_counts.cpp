#include "declared_counts.h"

#include "Io_error.h"

#include <unistd.h>
#include <algorithm>
#include <cctype>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <vector>

namespace fs = std::filesystem;

namespace cgal_policies {
namespace io {
namespace {

// Counts are read as long doubles: a forged count may be near 2^64, and its bytes beyond that.
struct Declared_element {
  std::string name;
  long double count = 0;
  long double min_bytes = 0;  // the fewest bytes one element can take in the file
};

// The least a vertex and a face take once read: a point of three doubles, and an index list.
constexpr long double kMemoryPerVertex = 24, kMemoryPerFace = 48;

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return text;
}

std::optional<long double> parse_count(const std::string& token) {
  if (token.empty() ||
      !std::all_of(token.begin(), token.end(), [](unsigned char c) { return std::isdigit(c); }))
    return std::nullopt;
  return std::stold(token);
}

std::string count_text(long double count) {
  std::ostringstream text;
  text.precision(20);
  text << count;
  return text.str();
}

// Checks elements declared in `header_bytes` bytes against the rest of a file of `file_bytes`.
void check_elements(const std::string& path, const std::vector<Declared_element>& elements,
                    long double header_bytes, long double file_bytes, long double slack) {
  long double needed = 0, memory = 0;
  std::string declared;
  for (const Declared_element& e : elements) {
    needed += e.count * e.min_bytes;
    memory += e.count * (e.name == "vertex"                         ? kMemoryPerVertex
                         : e.name == "face" || e.name == "triangle" ? kMemoryPerFace
                                                                    : 0);
    if (e.count > 0)
      declared += (declared.empty() ? "" : " and ") + count_text(e.count) + " " +
                  (e.count == 1         ? e.name
                   : e.name == "vertex" ? "vertices"
                                        : e.name + "s");
  }
  const long double body = file_bytes - header_bytes;
  if (needed - slack > body)
    throw Io_error(Io_error::Kind::unreadable_input,
                   path + ": declares " + declared + " but holds " + count_text(body) +
                       " bytes after its header, fewer than " + count_text(needed - slack) +
                       " (truncated?)");
  const long double physical =
      (long double)::sysconf(_SC_PHYS_PAGES) * (long double)::sysconf(_SC_PAGE_SIZE);
  if (physical > 0 && memory > physical)
    throw Io_error(Io_error::Kind::unreadable_input,
                   path + ": declares " + declared + ", more than this machine's memory can hold");
}

// ASCII OFF: [C][N][ST][4]OFF or nOFF DIM, then the vertex, face and edge counts, '#' comments
// anywhere. After the face count, a vertex takes at least " 0 0 0", a face at least " 0" (which
// the reader refuses).
void check_off(const std::string& path, std::ifstream& in, long double file_bytes) {
  std::string head(4096, '\0');
  in.read(&head[0], std::streamsize(head.size()));
  head.resize(std::size_t(in.gcount()));
  std::vector<std::string> tokens;
  std::size_t at = 0;
  // Up to the face count, whose end is where the elements begin.
  while (tokens.size() < 4 && at < head.size()) {
    if (head[at] == '#') {
      at = std::min(head.find('\n', at), head.size());
    } else if (std::isspace(static_cast<unsigned char>(head[at]))) {
      ++at;
    } else {
      const std::size_t end = std::min(head.find_first_of(" \t\r\n#", at), head.size());
      tokens.push_back(head.substr(at, end - at));
      at = end;
      const std::string& keyword = tokens[0];
      if (keyword.size() < 3 || keyword.compare(keyword.size() - 3, 3, "OFF") != 0) return;
      if (tokens.size() == 2 && tokens[1] == "BINARY") return;  // binary counts: not parsed
      if (tokens.size() == 3 && keyword.find("nOFF") == std::string::npos) break;
    }
  }
  const std::size_t first = tokens.size() == 4 ? 2 : 1;  // after nOFF's dimension
  if (tokens.size() < first + 2) return;
  const auto vertices = parse_count(tokens[first]), faces = parse_count(tokens[first + 1]);
  if (!vertices || !faces) return;
  check_elements(path, {{"vertex", *vertices, 6}, {"face", *faces, 2}}, at, file_bytes, 0);
}

// PLY: each element's properties give the fewest bytes it takes, in ASCII (a digit and a
// separator each) or binary (each scalar's size, a list's count alone).
void check_ply(const std::string& path, std::ifstream& in, long double file_bytes) {
  static const std::map<std::string, int> kSizes = {
      {"char", 1},  {"uchar", 1},   {"int8", 1},   {"uint8", 1},  {"short", 2}, {"ushort", 2},
      {"int16", 2}, {"uint16", 2},  {"int", 4},    {"uint", 4},   {"int32", 4}, {"uint32", 4},
      {"float", 4}, {"float32", 4}, {"double", 8}, {"float64", 8}};
  std::vector<Declared_element> elements;
  bool ascii = false;
  std::string line;
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::istringstream words(line);
    std::string word;
    words >> word;
    if (word == "end_header") break;
    if (word == "format") {
      words >> word;
      ascii = word == "ascii";
    } else if (word == "element") {
      std::string name, count;
      words >> name >> count;
      const auto parsed = parse_count(count);
      if (!parsed) return;
      elements.push_back({name, *parsed, 0});
    } else if (word == "property" && !elements.empty()) {
      std::string type;
      words >> type;
      if (type == "list") words >> type;  // the type of the count: a list may be empty
      const auto size = kSizes.find(type);
      if (size == kSizes.end()) return;
      elements.back().min_bytes += ascii ? 2 : size->second;
    }
  }
  if (!in || line != "end_header") return;
  check_elements(path, elements, (long double)in.tellg(), file_bytes, ascii ? 1 : 0);
}

// Binary STL: an 80-byte header, a 32-bit little-endian triangle count, 50 bytes a triangle. A
// file that starts with "solid" may be ASCII, whose text is no count: the reader tells.
void check_stl(const std::string& path, std::ifstream& in, long double file_bytes) {
  char header[84];
  if (!in.read(header, sizeof header)) return;
  if (lower(std::string(header, 5)) == "solid") return;
  const unsigned char* count_bytes = reinterpret_cast<const unsigned char*>(header + 80);
  const std::uint32_t triangles =
      std::uint32_t(count_bytes[0]) | std::uint32_t(count_bytes[1]) << 8 |
      std::uint32_t(count_bytes[2]) << 16 | std::uint32_t(count_bytes[3]) << 24;
  check_elements(path, {{"triangle", (long double)triangles, 50}}, 84, file_bytes, 0);
}

}  // namespace

void check_declared_counts(const std::string& path) {
  std::error_code ec;
  const std::uintmax_t size = fs::file_size(path, ec);
  if (ec) return;  // the reader reports it
  std::ifstream in(path, std::ios::binary);
  const std::string ext = lower(fs::path(path).extension().string());
  if (ext == ".off")
    check_off(path, in, size);
  else if (ext == ".ply")
    check_ply(path, in, size);
  else if (ext == ".stl")
    check_stl(path, in, size);
}

}  // namespace io
}  // namespace cgal_policies
