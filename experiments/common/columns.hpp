// What the experiments' protocols and reports share: a sweep of every index in index order, and a
// field or function of every row as a table column.
#pragma once
#include <cstddef>
#include <functional>
#include <numeric>
#include <vector>

namespace granrepro::experiments {

// Sweep points 0 .. n - 1, in index order.
inline std::vector<long> index_order(std::size_t n) {
    std::vector<long> order(n);
    std::iota(order.begin(), order.end(), 0L);
    return order;
}

// f (a member pointer or a function) of every row, in order.
template <class Rows, class F>
std::vector<double> column(const Rows& rows, F&& f) {
    std::vector<double> v;
    for (const auto& row : rows) v.push_back(double(std::invoke(f, row)));
    return v;
}

} // namespace granrepro::experiments
