#pragma once
// The level curves of a scalar field over a rectangle of a plane (marching squares, Lorensen and
// Cline's cubes in two dimensions): the field sampled on a grid of cells, each cell crossed where
// its corners lie on both sides of the level, each crossing refined on its cell edge by bisection
// of the field itself, so that a curve's points lie on the level to the bisection's precision,
// and the crossings chained cell to cell into polylines.
#include <functional>
#include <vector>
#include <glm/glm.hpp>

namespace shadowlab {

using Polyline = std::vector<glm::dvec3>;

// A field over world points: NaN where it is not defined (a cell with such a corner is left out).
using ScalarField = std::function<double(const glm::dvec3&)>;

// A rectangle [min, max] of a plane's (s, t), the point at (s, t) being origin + s along + t across,
// cut into cells.x × cells.y cells.
struct PlaneGrid {
    glm::dvec3 origin{0.0}, along{1, 0, 0}, across{0, 1, 0};
    glm::dvec2 min{0.0}, max{1.0};
    glm::ivec2 cells{1};

    glm::dvec3 point(int i, int j) const;  // the sample at corner (i, j), 0 <= i <= cells.x, 0 <= j <= cells.y
    glm::dvec2 cell_size() const { return (max - min) / glm::dvec2(cells); }
};

// The field at every corner of the grid, row by row (j major).
struct GridSamples {
    PlaneGrid grid;
    std::vector<double> values;

    double at(int i, int j) const { return values[static_cast<size_t>(j) * (grid.cells.x + 1) + i]; }
};
GridSamples sample_field(const PlaneGrid& grid, const ScalarField& field);

// The curves where `field` equals `level`, from its samples: each a polyline, open where it leaves
// the grid or the field's domain, closed (first point repeated last) around a loop.
std::vector<Polyline> level_curves(const GridSamples& samples, const ScalarField& field, double level);
// The same for several levels, increasing, in one pass over the cells: each cell visits only the
// levels between its corners' least and greatest values. One list of curves per level.
std::vector<std::vector<Polyline>> level_curves(const GridSamples& samples, const ScalarField& field,
                                                const std::vector<double>& levels);

}  // namespace shadowlab
