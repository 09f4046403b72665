// How much of a list of rectangles a rectangle covers, for many rectangles whose edges come from
// a few values along x and y (placeCaption's candidates, issue 42): the list is spread over the
// grid of those edges once, and a rectangle's sum is four look-ups in the grid's running sums
// (a 2-D prefix sum) instead of a pass over the list.
//
// The areas come out close to overlapArea's sums, not to the bit (a sum of doubles depends on its
// order): error() bounds how far, for any order of the sum. What is exact is whether a rectangle
// covers anything at all: touches() counts, in whole numbers, the rectangles of the list sharing
// positive area with it, their edges and its own compared as overlapArea compares them.
#pragma once

#include "camera.h"

#include <cstdint>
#include <vector>

class CoverGrid {
  public:
    // Spreads `rects` over the grid with edges `xs` along x and `ys` along y (each sorted, no two
    // equal, finite, at least two). A rectangle's edges are x and x + width (as summed in doubles),
    // and y and y + height; the parts outside the grid are left out.
    void build(const std::vector<double>& xs, const std::vector<double>& ys,
               const std::vector<ScreenRect>& rects);

    // The area of the list inside the grid's rectangle from edge (i0, j0) to edge (i1, j1) (the
    // indices in xs and ys, i0 <= i1, j0 <= j1), each rectangle's overlap counted once per
    // rectangle of the list: within error() of overlapArea's sum over the list in any order.
    double area(std::size_t i0, std::size_t j0, std::size_t i1, std::size_t j1) const {
        return at(area_, i1, j1) - at(area_, i0, j1) - at(area_, i1, j0) + at(area_, i0, j0);
    }
    // Zero exactly when no rectangle of the list shares positive area with that rectangle.
    std::int64_t touches(std::size_t i0, std::size_t j0, std::size_t i1, std::size_t j1) const {
        return at(touches_, i1, j1) - at(touches_, i0, j1) - at(touches_, i1, j0) +
               at(touches_, i0, j0);
    }
    // How far area() may be from a sum of overlapArea's areas over the list, in any order.
    double error() const { return error_; }

  private:
    template <typename T>
    static T at(const std::vector<T>& sums, std::size_t i, std::size_t j, std::size_t rows) {
        return sums[i * rows + j];
    }
    template <typename T> T at(const std::vector<T>& sums, std::size_t i, std::size_t j) const {
        return at(sums, i, j, ny_);
    }

    std::size_t nx_ = 0, ny_ = 0; // edges along x and y
    // The running sums from edge (0, 0) to edge (i, j) at i * ny_ + j: of the areas, and of the
    // (rectangle, cell) pairs sharing positive area.
    std::vector<double> area_;
    std::vector<std::int64_t> touches_;
    double error_ = 0.0;
};
