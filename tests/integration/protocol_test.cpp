// harness/protocol.hpp: an interrupted sweep resumes its saved points, and a point saved by a build
// whose Outcome had other fields is recomputed instead of failing to read (issue 28).
#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <fstream>

#include "cli_support.hpp"
#include "harness/protocol.hpp"

namespace fs = std::filesystem;
using namespace granrepro;
using namespace cli_support;

namespace {

struct ToySpec {
    long n = 0;
    template <class V> void fields(V&& v) { v("n", n); }
};

std::atomic<int> computed{0};

// The same experiment before and after its outcome gained a field.
struct OutcomeV1 {
    double x = 0;
    template <class V> void fields(V&& v) { v("x", x); }
};
struct OutcomeV2 {
    double x = 0;
    std::vector<double> y;
    template <class V> void fields(V&& v) { v("x", x), v("y", y); }
};

template <class Out>
struct Toy {
    static constexpr const char* name = "toy";
    using Spec = ToySpec;
    using Outcome = Out;
    static void validate(const ParameterSet&) {}
    static std::vector<long> points(const ToySpec& s) {
        std::vector<long> order;
        for (long i = s.n - 1; i >= 0; --i) order.push_back(i);
        return order;
    }
    static Outcome compute(const ToySpec&, long i, const PointContext&) {
        ++computed;
        Outcome o;
        o.x = 0.5 * double(i);
        if constexpr (requires { o.y; }) o.y = {double(i), 2.0 * double(i)};
        return o;
    }
    static Result report(const ToySpec& s, const Swept<Outcome>& swept, const RunContext&) {
        Result r;
        double sum = 0;
        for (const Outcome& o : swept.outcomes) sum += o.x;
        r.add_scalar("sum", sum, "1", "sum of x");
        r.add_scalar("n", double(s.n), "1", "points");
        return r;
    }
};

double value(const Result& r, const char* name) { return r.find_scalar(name)->value; }

} // namespace

TEST(Protocol, ResumesSavedPointsAndRecomputesThoseOfAnotherOutcomeLayout) {
    const TempPath work("protocol");
    fs::create_directories(work);
    const fs::path toml = work / "toy.toml";
    std::ofstream(toml) << "[parameters.n]\nvalue = 4\nunit = \"1\"\nrange = \"[1, 100]\"\nhelp = \"points\"\nsource = \"test\"\n";
    const ParameterSet params = ParameterSet::load(toml, Scale::Quick);
    const RunContext ctx{params, Scale::Quick, 7, 1, true, work / "checkpoints", 60.0};

    const Experiment v1 = protocol_experiment<Toy<OutcomeV1>>();
    const Experiment v2 = protocol_experiment<Toy<OutcomeV2>>();
    EXPECT_TRUE(v1.distributed); // point files saved: ranks and shards may share them

    computed = 0;
    const Result first = v1.run(ctx);
    EXPECT_EQ(computed, 4);
    EXPECT_EQ(value(first, "sum"), 0.5 * (0 + 1 + 2 + 3));

    computed = 0; // the same build again: every point is resumed, none computed
    const Result again = v1.run(ctx);
    EXPECT_EQ(computed, 0);
    EXPECT_EQ(value(again, "sum"), value(first, "sum"));

    computed = 0; // a build whose outcome has another field: recomputed, not misread
    const Result changed = v2.run(ctx);
    EXPECT_EQ(computed, 4);
    EXPECT_EQ(value(changed, "sum"), value(first, "sum"));
}

TEST(Protocol, OutcomeLayoutNamesFieldsAndKinds) {
    EXPECT_EQ(json_fields_schema<OutcomeV1>(), "{x:f,}");
    EXPECT_EQ(json_fields_schema<OutcomeV2>(), "{x:f,y:[f],}");
    EXPECT_NE(json_fields_schema<OutcomeV1>(), json_fields_schema<ToySpec>()); // a long is not a double
}

// `verify` reads outcomes stored by an earlier build: a field added since keeps its default there,
// while a resume (strict) refuses the JSON.
TEST(Protocol, StoredOutcomesOfAnEarlierLayoutReadLeniently) {
    OutcomeV1 old;
    old.x = 2.5;
    const nlohmann::json stored = to_json_fields(old);
    EXPECT_THROW(from_json_fields<OutcomeV2>(stored), nlohmann::json::exception);
    const OutcomeV2 now = from_json_fields_lenient<OutcomeV2>(stored);
    EXPECT_EQ(now.x, 2.5);
    EXPECT_TRUE(now.y.empty());
}
