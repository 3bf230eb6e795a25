#pragma once
// A face of more than three corners cut into triangles, as Assimp's aiProcess_Triangulate would: that
// step asserts and aborts the program on some files (Assimp 5.2, invalid/OutOfMemory.off), so
// ShadowLab reads faces as the file gives them and cuts them here.
#include <array>
#include <span>
#include <vector>
#include <glm/glm.hpp>

namespace shadowlab {

// The n - 2 triangles of the polygon whose corners are `corners` (indices into `vertices`, in the
// file's order), wound as the polygon is. A convex face is fanned from its first corner (as Assimp
// cuts it); a concave one is ear-clipped in the plane of its Newell normal, so that it keeps its
// outline; a face too twisted to have an ear (or of more than
// kMaxEarClippedCorners corners) is cut as a fan from its first corner.
std::vector<std::array<int, 3>> triangulate_polygon(const std::vector<glm::dvec3>& vertices,
                                                    std::span<const int> corners);

// Ear clipping costs n² per face; beyond this a face is fanned.
inline constexpr std::size_t kMaxEarClippedCorners = 1024;

}  // namespace shadowlab
