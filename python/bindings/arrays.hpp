#pragma once
// Per-pixel vectors of core (row-major, row 0 at the top) as NumPy arrays, copied.
#include <algorithm>
#include <stdexcept>
#include <vector>
#include <pybind11/numpy.h>

namespace shadowlab::python {

// A height x width array (height x width x channels with channels > 1) of `values`, each converted to T.
template <class T, class Value>
pybind11::array_t<T> image_array(const std::vector<Value>& values, int width, int height, int channels = 1) {
    const size_t count = size_t(width) * size_t(height) * size_t(channels);
    if (values.size() != count)
        throw std::logic_error("image_array: " + std::to_string(values.size()) + " values for " +
                               std::to_string(count) + " pixels");
    std::vector<pybind11::ssize_t> shape{height, width};
    if (channels > 1) shape.push_back(channels);
    pybind11::array_t<T> out(shape);
    std::transform(values.begin(), values.end(), out.mutable_data(), [](const Value& v) { return T(v); });
    return out;
}

}  // namespace shadowlab::python
