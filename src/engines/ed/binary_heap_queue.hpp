// Indexed binary min-heap holding exactly one pending event time per particle (Lubachevsky's
// "one event per particle" scheme): update(id, t) re-keys in O(log N), top is O(1).
// Ties are broken by id so that the pop order is a total order independent of the heap layout;
// a checkpoint that rebuilds the heap therefore resumes bit-identically.
#pragma once
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "engines/ed/huge_page_allocator.hpp"

namespace granrepro {

class BinaryHeapQueue {
public:
    BinaryHeapQueue() = default;
    explicit BinaryHeapQueue(std::size_t n) { reset(n); }

    // All ids 0..n-1 present with time +infinity.
    void reset(std::size_t n) {
        heap_.resize(n);
        pos_.resize(n);
        for (std::size_t k = 0; k < n; ++k) {
            heap_[k] = {kInf, static_cast<std::int32_t>(k)};
            pos_[k] = static_cast<std::int32_t>(k);
        }
    }
    // Replace all keys at once (O(N) heapify); times[i] belongs to id i.
    template <class Vec>
    void rebuild(const Vec& times) {
        reset(times.size());
        for (std::size_t k = 0; k < times.size(); ++k) heap_[k].t = times[k];
        for (std::size_t k = heap_.size() / 2; k-- > 0;) sift_down(k);
    }

    std::size_t size() const { return heap_.size(); }
    std::int32_t top_id() const { return heap_[0].id; }
    double top_time() const { return heap_[0].t; }
    double time_of(std::int32_t id) const { return heap_[pos_[id]].t; }

    void update(std::int32_t id, double t) {
        const std::size_t k = static_cast<std::size_t>(pos_[id]);
        const double old = heap_[k].t;
        heap_[k].t = t;
        if (t <= old) sift_up(k);
        else sift_down(k);
    }

    std::size_t memory_bytes() const {
        return heap_.capacity() * sizeof(Node) + pos_.capacity() * sizeof(std::int32_t);
    }

private:
    static constexpr double kInf = std::numeric_limits<double>::infinity();
    struct Node {
        double t;
        std::int32_t id;
    };
    static bool less(const Node& a, const Node& b) { return a.t < b.t || (a.t == b.t && a.id < b.id); }

    void place(std::size_t k, const Node& nd) {
        heap_[k] = nd;
        pos_[nd.id] = static_cast<std::int32_t>(k);
    }
    void sift_up(std::size_t k) {
        const Node nd = heap_[k];
        while (k > 0) {
            const std::size_t p = (k - 1) / 2;
            if (!less(nd, heap_[p])) break;
            place(k, heap_[p]);
            k = p;
        }
        place(k, nd);
    }
    void sift_down(std::size_t k) {
        const Node nd = heap_[k];
        const std::size_t n = heap_.size();
        for (;;) {
            std::size_t c = 2 * k + 1;
            if (c >= n) break;
            if (c + 1 < n && less(heap_[c + 1], heap_[c])) ++c;
            if (!less(heap_[c], nd)) break;
            place(k, heap_[c]);
            k = c;
        }
        place(k, nd);
    }

    HugeVector<Node> heap_;
    HugeVector<std::int32_t> pos_;
};

} // namespace granrepro
