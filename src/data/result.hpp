// What an experiment hands back: tables of columns (curves) and named scalars, each with units.
// The writer turns them into data.h5, summary.json and the tab-separated files gnuplot reads.
#pragma once
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <vector>

#include "data/outputs.hpp"

namespace granrepro {

struct Column {
    std::string name;
    std::string unit;
    std::vector<double> values;
};

struct Table {
    std::string name;        // file-name safe, e.g. "dv_vs_vy"
    std::string description; // one line
    std::vector<Column> columns;

    Column& add(std::string name, std::string unit) {
        columns.push_back({std::move(name), std::move(unit), {}});
        return columns.back();
    }
    // Several columns at once, in order: t.add({{"t", "s", times}, {"K", "J", energies}}).
    struct Values {
        std::string name, unit;
        const std::vector<double>& values;
    };
    void add(std::initializer_list<Values> cols) {
        for (const Values& c : cols) add(c.name, c.unit).values = c.values;
    }
};

struct Scalar {
    std::string name;
    double value = 0;
    std::string unit;
    std::string description;
};

struct Result {
    std::vector<Table> tables;
    std::vector<Scalar> scalars;

    // By name, for the harness and tests; experiments write through handles (put and table(handle)
    // below; tests/unit/declared_outputs_test.cpp finds any experiment that calls these). A name
    // given twice is a bug in the experiment; it is refused here, before anything is written,
    // rather than by HDF5 half-way through data.h5.
    Table& add_table(std::string name, std::string description) {
        for (const auto& t : tables)
            if (t.name == name) throw std::logic_error("result table '" + name + "' added twice");
        tables.push_back({std::move(name), std::move(description), {}});
        return tables.back();
    }
    void add_scalar(std::string name, double value, std::string unit, std::string description) {
        if (find_scalar(name)) throw std::logic_error("result scalar '" + name + "' added twice");
        scalars.push_back({std::move(name), value, std::move(unit), std::move(description)});
    }
    // Through a handle (data/outputs.hpp), the way experiments write: n fills the pattern's <n> and <w>,
    // more is appended to the declared description.
    void put(const ScalarOut& h, double value, std::initializer_list<NamePart> n = {}, std::string_view more = {}) {
        add_scalar(fill_pattern(h.pattern, h.words, n), value, h.unit, h.description + std::string(more));
    }
    Table& table(const TableOut& h, std::initializer_list<NamePart> n = {}, std::string_view more = {}) {
        return add_table(fill_pattern(h.pattern, h.words, n), h.description + std::string(more));
    }
    // A table whose name was made from the same handle elsewhere (fill_pattern in compute, carried
    // by a sweep point); refused unless the handle makes that name.
    Table& table_named(const TableOut& h, std::string name, std::string_view more = {}) {
        if (!makes_name(h.pattern, h.words, name))
            throw std::logic_error("table '" + name + "' is not one handle '" + h.pattern + "' makes");
        return add_table(std::move(name), h.description + std::string(more));
    }
    const Scalar* find_scalar(const std::string& name) const {
        for (const auto& s : scalars)
            if (s.name == name) return &s;
        return nullptr;
    }
};

} // namespace granrepro
