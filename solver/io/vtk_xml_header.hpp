#pragma once
// The opening of a VTK XML PolyData file (.vtp) whose binary blocks carry a UInt64 byte
// count in this machine's byte order; analysis/contact_network.cpp and
// analysis/neighbourhood_dump.cpp write the rest.
#include <cstdint>
#include <string>

namespace sphdem {

inline std::string vtk_polydata_opening() {
  const std::uint16_t one = 1;
  const bool little = *reinterpret_cast<const std::uint8_t*>(&one) == 1;
  return std::string(
             "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"") +
         (little ? "LittleEndian" : "BigEndian") + "\" header_type=\"UInt64\">\n";
}

}  // namespace sphdem
