// symrep/lang/builtins.cpp -- the builtin registry and argument checking.
#include "symrep/lang/builtins.h"

#include <memory>

#include <algorithm>
#include <climits>
#include <sstream>

namespace symrep::lang {

std::string value::kind() const {
    switch (v.index()) {
        case 0: return "nothing";
        case 1: return "boolean";
        case 2: return "expression";
        case 3: return "string";
        case 4: return "list";
        case 5: return "algebra";
        case 6: return "element";
        case 7: return "problem";
        default: return "solution";
    }
}

std::string value::a_kind() const {
    const std::string k = kind();
    return (k == "expression" || k == "element" || k == "algebra" ? "an " : "a ") + k;
}

void add_builtins(registry& r, const std::string& section, std::vector<builtin_declaration> table) {
    for (builtin_declaration& d : table) {
        builtin b;
        b.name = std::move(d.name);
        b.signature = std::move(d.signature);
        b.summary = std::move(d.summary);
        b.equation = std::move(d.equation);
        b.example = std::move(d.example);
        b.section = section;
        b.min_args = d.min_args;
        b.max_args = d.max_args;
        b.options = std::move(d.options);
        // the body sees the builtin as registered (without fn: no cycle through the shared copy)
        auto self = std::make_shared<const builtin>(b);
        b.fn = [self, body = std::move(d.body)](const std::vector<value>& a, context& c) { return body(*self, a, c); };
        r.add(std::move(b));
    }
}

void registry::add(builtin b) {
    if (table_.count(b.name)) throw std::logic_error("builtin registered twice: " + b.name);
    std::string key = b.name;
    table_.emplace(std::move(key), std::move(b));
}

const builtin* registry::find(const std::string& name) const {
    auto it = table_.find(name);
    return it == table_.end() ? nullptr : &it->second;
}

std::vector<const builtin*> registry::all() const {
    std::vector<const builtin*> v;
    for (const auto& [k, b] : table_) v.push_back(&b);
    std::stable_sort(v.begin(), v.end(), [](const builtin* a, const builtin* b) {
        return a->section != b->section ? a->section < b->section : a->name < b->name;
    });
    return v;
}

namespace {
const value& checked(const std::vector<value>& args, std::size_t i, const builtin& b) {
    if (i >= args.size())
        throw type_error(b.name + ": missing argument " + std::to_string(i + 1) + " (usage: " +
                         b.signature + ")");
    return args[i];
}
[[noreturn]] void wrong(const std::vector<value>& args, std::size_t i, const builtin& b,
                        const std::string& wanted) {
    throw type_error(b.name + ": argument " + std::to_string(i + 1) + " must be " + wanted +
                     ", not " + args[i].a_kind() +
                     " (usage: " + b.signature + ")");
}
}  // namespace

const element& arg_element(const std::vector<value>& args, std::size_t i, const builtin& b) {
    const value& v = checked(args, i, b);
    if (!v.is_element()) wrong(args, i, b, "an algebra element");
    return v.as_element();
}

const algebra_ptr& arg_algebra(const std::vector<value>& args, std::size_t i, const builtin& b) {
    const value& v = checked(args, i, b);
    if (!v.is_algebra()) wrong(args, i, b, "an algebra");
    return v.as_algebra();
}

const GiNaC::ex& arg_ex(const std::vector<value>& args, std::size_t i, const builtin& b) {
    const value& v = checked(args, i, b);
    if (!v.is_ex()) wrong(args, i, b, "an expression");
    return v.as_ex();
}

const list& arg_list(const std::vector<value>& args, std::size_t i, const builtin& b) {
    const value& v = checked(args, i, b);
    if (!v.is_list()) wrong(args, i, b, "a list");
    return v.as_list();
}

const std::string& arg_string(const std::vector<value>& args, std::size_t i, const builtin& b) {
    const value& v = checked(args, i, b);
    if (!v.is_string()) wrong(args, i, b, "a string");
    return v.as_string();
}

long arg_int(const std::vector<value>& args, std::size_t i, const builtin& b, long min, long max) {
    const value& v = checked(args, i, b);
    std::ostringstream range;
    range << "an integer from " << min << " to " << max;
    if (!v.is_ex() || !GiNaC::is_a<GiNaC::numeric>(v.as_ex()) ||
        !GiNaC::ex_to<GiNaC::numeric>(v.as_ex()).is_integer())
        wrong(args, i, b, range.str());
    const GiNaC::numeric k = GiNaC::ex_to<GiNaC::numeric>(v.as_ex());
    if (k < min || k > max) {
        std::ostringstream os;
        os << b.name << ": argument " << i + 1 << " is " << k << ", but must be " << range.str();
        throw type_error(os.str());
    }
    return k.to_long();
}

const GiNaC::symbol& arg_symbol(const std::vector<value>& args, std::size_t i, const builtin& b) {
    const value& v = checked(args, i, b);
    if (!v.is_ex() || !GiNaC::is_a<GiNaC::symbol>(v.as_ex())) wrong(args, i, b, "a symbol");
    return GiNaC::ex_to<GiNaC::symbol>(v.as_ex());
}

std::vector<GiNaC::ex> arg_ex_list(const std::vector<value>& args, std::size_t i, const builtin& b) {
    const list& l = arg_list(args, i, b);
    std::vector<GiNaC::ex> out;
    out.reserve(l.size());
    for (std::size_t k = 0; k < l.size(); ++k) {
        if (!l[k].is_ex())
            throw type_error(b.name + ": entry " + std::to_string(k) + " of argument " +
                             std::to_string(i + 1) + " must be an expression, not " +
                             l[k].a_kind() + " (usage: " + b.signature + ")");
        out.push_back(l[k].as_ex());
    }
    return out;
}

}  // namespace symrep::lang
