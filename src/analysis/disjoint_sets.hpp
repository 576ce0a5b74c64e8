// A disjoint-set forest (union-find with path halving) over 0 .. n-1: the chains of the crack
// search (crack_detector.cpp) and the hot bands of pipe-arching.
#pragma once
#include <cstddef>
#include <numeric>
#include <vector>

namespace granrepro {

struct DisjointSets {
    std::vector<int> up;
    explicit DisjointSets(std::size_t n) : up(n) { std::iota(up.begin(), up.end(), 0); }
    int find(int a) {
        while (up[std::size_t(a)] != a) a = up[std::size_t(a)] = up[std::size_t(up[std::size_t(a)])];
        return a;
    }
    void join(int a, int b) { up[std::size_t(find(a))] = find(b); }
};

} // namespace granrepro
