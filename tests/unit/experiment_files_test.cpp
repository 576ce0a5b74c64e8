// The experiment files (experiments/<name>.toml) as the one registry of what each experiment is:
// its paper (the report's papers come from here), its figures and its smoke scale, read by
// ExperimentInfo and printed by `granrepro list --json` (cli/listing.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <unistd.h>

#include "cli/listing.hpp"
#include "core/input_error.hpp"
#include "data/toml_file.hpp"
#include "harness/experiment.hpp"
#include "harness/runner.hpp"

using namespace granrepro;
namespace fs = std::filesystem;

// Experiments of one paper name it alike, so that a paper has one reference, label and citation
// wherever it is shown; two papers have two keys.
TEST(ExperimentFiles, ExperimentsOfOnePaperAgreeOnIt) {
    std::map<std::string, ExperimentInfo> first_of;
    for (const auto& e : experiment_registry()) {
        const ExperimentInfo info = experiment_info(e.name);
        EXPECT_FALSE(info.paper_key.empty() || info.paper_short.empty() || info.paper_citation.empty()) << e.name;
        const auto [it, fresh] = first_of.emplace(info.paper_key, info);
        if (fresh) continue;
        EXPECT_EQ(info.paper, it->second.paper) << e.name << " and " << it->second.name;
        EXPECT_EQ(info.paper_short, it->second.paper_short) << e.name << " and " << it->second.name;
        EXPECT_EQ(info.paper_citation, it->second.paper_citation) << e.name << " and " << it->second.name;
    }
    for (const auto& [key, info] : first_of)
        for (const auto& [other_key, other] : first_of) {
            if (key != other_key) {
                EXPECT_NE(info.paper_short, other.paper_short) << key << " and " << other_key;
            }
        }
}

// Every experiment has a smoke scale its own parameters accept (the input fuzz test runs on it).
TEST(ExperimentFiles, EverySmokeScaleIsAccepted) {
    for (const auto& e : experiment_registry()) {
        RunOptions o;
        o.sets = experiment_info(e.name).smoke;
        EXPECT_FALSE(o.sets.empty()) << e.name << ": no [smoke] set";
        EXPECT_NO_THROW(resolve_parameters(e.name, o)) << e.name;
    }
}

// `list --json`: every registered experiment once, in registry order, as its file describes it.
TEST(ExperimentFiles, ListingFollowsTheRegistry) {
    const nlohmann::json listing = experiments_listing();
    const auto& registry = experiment_registry();
    ASSERT_EQ(listing.at("experiments").size(), registry.size());
    for (std::size_t i = 0; i < registry.size(); ++i) {
        const nlohmann::json& x = listing["experiments"][i];
        const ExperimentInfo info = experiment_info(registry[i].name);
        EXPECT_EQ(x.at("name"), registry[i].name);
        EXPECT_EQ(x.at("paper_key"), info.paper_key);
        EXPECT_EQ(x.at("figures").size(), info.figures.size());
        EXPECT_EQ(x.at("smoke"), nlohmann::json(info.smoke));
    }
}

// A figure id that does not start with its paper's key, and a smoke entry that is not name=value,
// are refused with the file and line.
TEST(ExperimentFiles, AFigureOfAnotherPaperOrABadSmokeEntryIsRefused) {
    const std::string head = "name = \"x\"\npaper = \"A, J. 1, 1 (2000)\"\npaper_key = \"a00\"\npaper_short = \"A (2000)\"\n"
                             "paper_citation = \"A. A, T, J. 1, 1 (2000)\"\ndescription = \"d\"\n";
    const fs::path file = fs::temp_directory_path() / ("experiment-files-" + std::to_string(::getpid()) + ".toml");
    auto refusal = [&](const std::string& text) {
        std::ofstream(file) << text;
        try {
            ExperimentInfo::load(file);
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    EXPECT_EQ(refusal(head + "[[figure]]\nid = \"a00-fig1\"\ncaption = \"c\"\n[smoke]\nset = [\"n=1\"]\n"), "accepted");
    std::string why = refusal(head + "[[figure]]\nid = \"b00-fig1\"\ncaption = \"c\"\n");
    EXPECT_NE(why.find("(line 7)"), std::string::npos) << why;
    EXPECT_NE(why.find("paper_key 'a00-'"), std::string::npos) << why;
    why = refusal(head + "[smoke]\nset = [\"n=1\", \"n\"]\n");
    EXPECT_NE(why.find("(line 8)"), std::string::npos) << why;
    EXPECT_NE(why.find("not name=value"), std::string::npos) << why;
    why = refusal(head + "[smoke]\nsets = [\"n=1\"]\n");
    EXPECT_NE(why.find("unknown key 'sets'"), std::string::npos) << why;
    why = refusal("name = \"x\"\npaper = \"p\"\ndescription = \"d\"\n");
    EXPECT_NE(why.find("paper_key"), std::string::npos) << why;
    fs::remove(file);
}

// ARCHITECTURE.md's worked example, "Adding a figure": the files a registered experiment must
// have besides its C++ (which the registry line proves). An experiment that misses one fails here,
// named with the file, instead of failing later in a figure target, a check or the report.
TEST(ExperimentFiles, EveryExperimentHasEveryFileOfTheWorkedExample) {
    const fs::path root = project_root();
    const toml::value captions = parse_toml_file(root / "python/granrepro/report/figures.toml", "figure captions");
    for (const auto& e : experiment_registry()) {
        const ExperimentInfo info = experiment_info(e.name);
        std::string folder = e.name;
        std::replace(folder.begin(), folder.end(), '-', '_');
        EXPECT_TRUE(fs::is_regular_file(root / "experiments" / (e.name + ".toml"))) << e.name;
        EXPECT_TRUE(fs::is_directory(root / "experiments" / folder)) << "experiments/" << folder << "/";
        EXPECT_TRUE(fs::is_regular_file(root / "expected" / (e.name + ".toml"))) << "expected/" << e.name << ".toml";
        EXPECT_FALSE(info.figures.empty()) << e.name << ": no [[figure]]";
        for (const auto& f : info.figures) {
            EXPECT_TRUE(fs::is_regular_file(root / "plots" / (f.id + ".gp"))) << "plots/" << f.id << ".gp";
            EXPECT_TRUE(captions.contains("figure") && captions.at("figure").contains(f.id))
                << "python/granrepro/report/figures.toml: no [figure.\"" << f.id << "\"] caption";
        }
    }
}
