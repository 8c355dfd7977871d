// Reads a fuzzer's bytes front to back as small numbers; past the end every read gives 0, so that
// any input decodes to something.
#ifndef CGAL_POLICIES_FUZZ_BYTE_READER_H
#define CGAL_POLICIES_FUZZ_BYTE_READER_H

#include <cstddef>
#include <cstdint>

namespace fuzz {

class Byte_reader {
 public:
  Byte_reader(const std::uint8_t* data, std::size_t size) : m_data(data), m_size(size) {}

  std::uint8_t u8() { return m_at < m_size ? m_data[m_at++] : 0; }
  std::uint16_t u16() { return std::uint16_t(u8() | (u8() << 8)); }
  std::int16_t i16() { return std::int16_t(u16()); }
  // In [0, 1].
  double unit() { return u16() / 65535.0; }
  bool empty() const { return m_at >= m_size; }

 private:
  const std::uint8_t* m_data;
  std::size_t m_size;
  std::size_t m_at = 0;
};

}  // namespace fuzz

#endif  // CGAL_POLICIES_FUZZ_BYTE_READER_H
