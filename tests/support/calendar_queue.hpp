// Indexed calendar (bucket) queue with one pending event time per id (Brown 1988; the ED use is
// Marin et al. 1993). Bucket b = floor(t/width) mod nbuckets holds an unsorted doubly linked
// list; the minimum is searched from the current bucket on, accepting only entries of the
// current "year". With ~1-2 entries per bucket, top/update are O(1) on average. The width is
// re-estimated from the spread of pending times every few N updates.
// Same interface and the same total order on (time, id) as BinaryHeapQueue. Test-only: the
// engine tests run BasicEdEngine<CalendarQueue> to show the engine is queue-agnostic (the
// engine's choice of queue: the note above EdEngine in ed_engine.hpp).
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "engines/ed/huge_page_allocator.hpp"

namespace granrepro {

class CalendarQueue {
public:
    CalendarQueue() = default;
    explicit CalendarQueue(std::size_t n) { reset(n); }

    void reset(std::size_t n) { rebuild(HugeVector<double>(n, kInf)); }
    template <class Vec>
    void rebuild(const Vec& times) {
        t_.assign(times.begin(), times.end());
        const std::size_t n = t_.size();
        next_.assign(n, -1);
        prev_.assign(n, -1);
        bucket_.assign(n, -1);
        std::size_t nb = 1;
        while (nb < n) nb <<= 1;
        nb_ = nb;
        mask_ = nb - 1;
        choose_width();
        head_.assign(nb_ + 1, -1); // last list: infinite (or out-of-range) times
        cur_vb_ = std::numeric_limits<std::int64_t>::max();
        for (std::size_t i = 0; i < n; ++i) insert(static_cast<std::int32_t>(i));
        cache_ = -1;
        updates_ = 0;
        check_at_ = 64;
    }

    std::size_t size() const { return t_.size(); }
    std::int32_t top_id() { find_min(); return cache_; }
    double top_time() { find_min(); return t_[cache_]; }
    double time_of(std::int32_t id) const { return t_[id]; }
    // No cheap guess of the next-but-one entry: no prefetching.
    std::int32_t runner_up() const { return -1; }

    void update(std::int32_t id, double t) {
        remove(id);
        const double old = t_[id];
        t_[id] = t;
        insert(id);
        if (cache_ >= 0) {
            if (id == cache_) {
                if (t > old) cache_ = -1;
            } else if (less(id, cache_)) {
                cache_ = id;
            }
        }
        if (++updates_ >= check_at_) maybe_resize();
    }

    std::size_t memory_bytes() const {
        return t_.capacity() * sizeof(double) +
               (next_.capacity() + prev_.capacity() + bucket_.capacity() + head_.capacity()) * sizeof(std::int32_t);
    }

private:
    static constexpr double kInf = std::numeric_limits<double>::infinity();
    static constexpr double kMaxVb = 4.0e18;

    bool less(std::int32_t a, std::int32_t b) const { return t_[a] < t_[b] || (t_[a] == t_[b] && a < b); }
    // Virtual bucket number; -1 for times that go to the overflow list.
    std::int64_t vbucket(double t) const {
        const double v = std::floor(t * inv_w_);
        if (!(v < kMaxVb) || !(v > -kMaxVb)) return -1;
        return static_cast<std::int64_t>(v);
    }
    std::int32_t list_of(std::int64_t vb) const {
        return vb == -1 ? static_cast<std::int32_t>(nb_) : static_cast<std::int32_t>(vb & static_cast<std::int64_t>(mask_));
    }
    void insert(std::int32_t id) {
        const std::int64_t vb = vbucket(t_[id]);
        if (vb != -1 && vb < cur_vb_) cur_vb_ = vb;
        const std::int32_t b = list_of(vb);
        bucket_[id] = b;
        prev_[id] = -1;
        next_[id] = head_[b];
        if (head_[b] >= 0) prev_[head_[b]] = id;
        head_[b] = id;
    }
    void remove(std::int32_t id) {
        const std::int32_t b = bucket_[id];
        if (prev_[id] >= 0) next_[prev_[id]] = next_[id]; else head_[b] = next_[id];
        if (next_[id] >= 0) prev_[next_[id]] = prev_[id];
    }
    void find_min() {
        if (cache_ >= 0) return;
        if (cur_vb_ != std::numeric_limits<std::int64_t>::max()) {
            for (std::size_t k = 0; k < nb_; ++k) {
                const std::int64_t vb = cur_vb_ + static_cast<std::int64_t>(k);
                std::int32_t best = -1;
                for (std::int32_t id = head_[list_of(vb)]; id >= 0; id = next_[id]) {
                    if (vbucket(t_[id]) != vb) continue;
                    if (best < 0 || less(id, best)) best = id;
                }
                if (best >= 0) {
                    cur_vb_ = vb;
                    cache_ = best;
                    return;
                }
            }
        }
        // Nothing within a year: direct search over everything (rare).
        std::int32_t best = -1;
        for (std::size_t b = 0; b <= nb_; ++b)
            for (std::int32_t id = head_[b]; id >= 0; id = next_[id])
                if (best < 0 || less(id, best)) best = id;
        cache_ = best;
        const std::int64_t vb = vbucket(t_[best]);
        cur_vb_ = vb == -1 ? std::numeric_limits<std::int64_t>::max() : vb;
    }
    // Width ~ 4 x (median of pending times above their minimum) / count: about three entries
    // per bucket near the front, where the searches happen. A median, unlike a mean, is not
    // dragged up by the few particles that have nothing to do for a long time.
    double estimate_width() const {
        double tmin = kInf;
        std::size_t cnt = 0;
        for (double t : t_) if (t < kInf) { tmin = std::min(tmin, t); ++cnt; }
        if (cnt < 2) return 1.0;
        HugeVector<double> sample;
        const std::size_t stride = std::max<std::size_t>(1, t_.size() / 2048);
        for (std::size_t i = 0; i < t_.size(); i += stride) if (t_[i] < kInf) sample.push_back(t_[i] - tmin);
        if (sample.empty()) return 1.0;
        auto mid = sample.begin() + static_cast<std::ptrdiff_t>(sample.size() / 2);
        std::nth_element(sample.begin(), mid, sample.end());
        const double w = 4.0 * *mid / static_cast<double>(cnt);
        return (w > 0.0 && std::isfinite(w)) ? w : 1.0;
    }
    void choose_width() {
        width_ = estimate_width();
        inv_w_ = 1.0 / width_;
    }
    // Checked after 64, 128, ... updates (then every 8N): a width chosen while the keys were
    // still all infinite is corrected long before it costs O(N) per search.
    void maybe_resize() {
        updates_ = 0;
        const double w = estimate_width();
        if (w > 2.0 * width_ || w < 0.5 * width_) {
            rebuild(HugeVector<double>(t_));
            return;
        }
        check_at_ = std::min(2 * check_at_, 8 * t_.size() + 64);
    }

    HugeVector<double> t_;
    HugeVector<std::int32_t> next_, prev_, bucket_, head_;
    std::size_t nb_ = 1, mask_ = 0;
    double width_ = 1.0, inv_w_ = 1.0;
    std::int64_t cur_vb_ = std::numeric_limits<std::int64_t>::max();
    std::int32_t cache_ = -1;
    std::size_t updates_ = 0;
    std::size_t check_at_ = 64;
};

} // namespace granrepro
