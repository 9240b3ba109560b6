#include "ground/reachability.h"

#include <algorithm>
#include <deque>
#include <set>
#include <unordered_set>

namespace envdesign::ground {
namespace {

// An atom in a schema: arguments >= 0 are parameter indexes, < 0 encode object -(id + 1).
struct SchemaAtom {
    int predicate = 0;
    std::vector<int> args;
};

struct Schema {
    int index = 0;
    std::vector<std::vector<bool>> allowed; // per parameter, per object
    std::vector<SchemaAtom> positive;       // positive preconditions, static ones included
    std::vector<SchemaAtom> negative_static;
    std::vector<std::pair<int, int>> equal, distinct;
    std::vector<SchemaAtom> adds;
};

int encode_object(int object) { return -(object + 1); }
int decode_object(int arg) { return -arg - 1; }

class Explorer {
public:
    Explorer(const pddl::Domain &domain, const pddl::Problem &problem, Reachability &out,
             const StopCheck &stop)
        : domain_(domain), problem_(problem), out_(out), stop_(stop) {}

    void run() {
        collect_objects();
        collect_predicates();
        for (std::size_t i = 0; i < domain_.actions.size(); ++i)
            schemas_.push_back(compile(static_cast<int>(i)));
        for (const auto &atom : problem_.init)
            add_atom(key_of(atom));
        for (auto &schema : schemas_)
            if (schema.positive.empty())
                join(schema, std::vector<int>(schema.allowed.size(), -1), 0);
        while (!queue_.empty()) {
            int atom = queue_.front();
            queue_.pop_front();
            trigger(atom);
            every_so_often();
        }
        out_.object_ids = object_ids_;
        out_.predicate_ids = predicate_ids_;
    }

private:
    void collect_objects() {
        auto add = [&](const pddl::TypedName &o) {
            if (object_ids_.count(o.name))
                return;
            object_ids_[o.name] = static_cast<int>(out_.objects.size());
            out_.objects.push_back(o.name);
            std::set<std::string> types = {"object"};
            for (std::string t : o.types)
                for (; t != "object" && types.insert(t).second;)
                    t = domain_.type_parent.count(t) ? domain_.type_parent.at(t) : "object";
            object_types_.push_back(std::move(types));
        };
        for (const auto &c : domain_.constants)
            add(c);
        for (const auto &o : problem_.objects)
            add(o);
    }

    void collect_predicates() {
        for (const auto &p : domain_.predicates) {
            predicate_ids_[p.name] = static_cast<int>(out_.predicates.size());
            out_.predicates.push_back(p.name);
            out_.is_fluent.push_back(false);
            by_argument_.emplace_back(p.parameters.size(),
                                      std::vector<std::vector<int>>(out_.objects.size()));
        }
        by_predicate_.resize(out_.predicates.size());
        triggers_.resize(out_.predicates.size());
        for (const auto &a : domain_.actions)
            for (const auto &l : a.effect)
                out_.is_fluent[predicate_ids_.at(l.atom.predicate)] = true;
    }

    SchemaAtom compile_atom(const pddl::Atom &atom, const std::map<std::string, int> &params) {
        SchemaAtom result{atom.predicate == "=" ? -1 : predicate_ids_.at(atom.predicate), {}};
        for (const auto &arg : atom.args) {
            auto it = params.find(arg);
            result.args.push_back(it != params.end() ? it->second
                                                     : encode_object(object_ids_.at(arg)));
        }
        return result;
    }

    Schema compile(int index) {
        const pddl::Action &action = domain_.actions[index];
        Schema schema;
        schema.index = index;
        std::map<std::string, int> params;
        for (const auto &p : action.parameters) {
            params[p.name] = static_cast<int>(params.size());
            std::vector<bool> allowed(out_.objects.size(), false);
            for (std::size_t o = 0; o < out_.objects.size(); ++o)
                for (const auto &t : p.types)
                    allowed[o] = allowed[o] || object_types_[o].count(t) > 0;
            schema.allowed.push_back(std::move(allowed));
        }
        for (const auto &l : action.precondition) {
            SchemaAtom atom = compile_atom(l.atom, params);
            if (atom.predicate < 0)
                (l.negated ? schema.distinct : schema.equal)
                    .emplace_back(atom.args[0], atom.args[1]);
            else if (!l.negated)
                schema.positive.push_back(std::move(atom));
            else if (!out_.is_fluent[atom.predicate])
                schema.negative_static.push_back(std::move(atom));
        }
        for (const auto &l : action.effect)
            if (!l.negated)
                schema.adds.push_back(compile_atom(l.atom, params));
        if (schema.positive.size() > 64)
            throw pddl::ParseError(action.location, "more than 64 positive preconditions");
        for (std::size_t i = 0; i < schema.positive.size(); ++i)
            triggers_[schema.positive[i].predicate].emplace_back(index, static_cast<int>(i));
        return schema;
    }

    AtomKey key_of(const pddl::Atom &ground_atom) const {
        AtomKey key{predicate_ids_.at(ground_atom.predicate)};
        for (const auto &arg : ground_atom.args)
            key.push_back(object_ids_.at(arg));
        return key;
    }

    void add_atom(AtomKey key) {
        auto [it, inserted] = out_.atom_index.emplace(key, static_cast<int>(out_.atoms.size()));
        if (!inserted)
            return;
        int id = it->second;
        int predicate = key[0];
        by_predicate_[predicate].push_back(id);
        for (std::size_t pos = 1; pos < key.size(); ++pos)
            by_argument_[predicate][pos - 1][key[pos]].push_back(id);
        out_.atoms.push_back(std::move(key));
        queue_.push_back(id);
    }

    // Binds the schema atom's parameters to the ground atom's objects; false on a clash.
    bool unify(const Schema &schema, const SchemaAtom &atom, const AtomKey &key,
               std::vector<int> &binding) const {
        for (std::size_t pos = 0; pos < atom.args.size(); ++pos) {
            int arg = atom.args[pos];
            int object = key[pos + 1];
            if (arg < 0) {
                if (decode_object(arg) != object)
                    return false;
            } else if (binding[arg] < 0) {
                if (!schema.allowed[arg][object])
                    return false;
                binding[arg] = object;
            } else if (binding[arg] != object) {
                return false;
            }
        }
        return true;
    }

    void trigger(int atom_id) {
        const AtomKey key = out_.atoms[atom_id];
        for (auto [schema_index, pre] : triggers_[key[0]]) {
            const Schema &schema = schemas_[schema_index];
            std::vector<int> binding(schema.allowed.size(), -1);
            if (unify(schema, schema.positive[pre], key, binding))
                join(schema, binding, std::uint64_t{1} << pre);
        }
    }

    // Chooses the unmatched precondition with the most bound arguments (fewest candidates).
    int next_precondition(const Schema &schema, const std::vector<int> &binding,
                          std::uint64_t done) const {
        int best = -1, best_bound = -1;
        for (std::size_t i = 0; i < schema.positive.size(); ++i) {
            if (done >> i & 1)
                continue;
            int bound = 0;
            for (int arg : schema.positive[i].args)
                bound += arg < 0 || binding[arg] >= 0;
            if (bound > best_bound)
                best = static_cast<int>(i), best_bound = bound;
        }
        return best;
    }

    const std::vector<int> &candidates(const SchemaAtom &atom,
                                       const std::vector<int> &binding) const {
        for (std::size_t pos = 0; pos < atom.args.size(); ++pos) {
            int arg = atom.args[pos];
            int object = arg < 0 ? decode_object(arg) : binding[arg];
            if (object >= 0)
                return by_argument_[atom.predicate][pos][object];
        }
        return by_predicate_[atom.predicate];
    }

    void join(const Schema &schema, std::vector<int> binding, std::uint64_t done) {
        int pre = next_precondition(schema, binding, done);
        if (pre < 0) {
            bind_free_parameters(schema, binding, 0);
            return;
        }
        const SchemaAtom &atom = schema.positive[pre];
        // Copy: emitting may add atoms to the very list being iterated.
        const std::vector<int> matches = candidates(atom, binding);
        for (int id : matches) {
            std::vector<int> extended = binding;
            if (unify(schema, atom, out_.atoms[id], extended))
                join(schema, std::move(extended), done | std::uint64_t{1} << pre);
        }
    }

    void bind_free_parameters(const Schema &schema, std::vector<int> &binding, std::size_t from) {
        while (from < binding.size() && binding[from] >= 0)
            ++from;
        if (from == binding.size()) {
            emit(schema, binding);
            return;
        }
        for (std::size_t o = 0; o < out_.objects.size(); ++o) {
            if (!schema.allowed[from][o])
                continue;
            binding[from] = static_cast<int>(o);
            bind_free_parameters(schema, binding, from + 1);
        }
        binding[from] = -1;
    }

    int resolve(int arg, const std::vector<int> &binding) const {
        return arg < 0 ? decode_object(arg) : binding[arg];
    }

    AtomKey instantiate(const SchemaAtom &atom, const std::vector<int> &binding) const {
        AtomKey key{atom.predicate};
        for (int arg : atom.args)
            key.push_back(resolve(arg, binding));
        return key;
    }

    // A clock read per step would cost more than the step.
    void every_so_often() {
        if (++steps_ % 4096 == 0)
            check(stop_);
    }

    void emit(const Schema &schema, const std::vector<int> &binding) {
        every_so_often();
        for (auto [a, b] : schema.equal)
            if (resolve(a, binding) != resolve(b, binding))
                return;
        for (auto [a, b] : schema.distinct)
            if (resolve(a, binding) == resolve(b, binding))
                return;
        for (const auto &atom : schema.negative_static)
            if (out_.is_reached(instantiate(atom, binding)))
                return;
        AtomKey instance{schema.index};
        instance.insert(instance.end(), binding.begin(), binding.end());
        if (!seen_instances_.insert(std::move(instance)).second)
            return;
        out_.actions.push_back({schema.index, binding});
        for (const auto &add : schema.adds)
            add_atom(instantiate(add, binding));
    }

    const pddl::Domain &domain_;
    const pddl::Problem &problem_;
    Reachability &out_;
    const StopCheck &stop_;
    std::uint64_t steps_ = 0;
    std::unordered_map<std::string, int> object_ids_, predicate_ids_;
    std::vector<std::set<std::string>> object_types_;
    std::vector<Schema> schemas_;
    std::vector<std::vector<std::pair<int, int>>> triggers_; // predicate -> (schema, precondition)
    std::vector<std::vector<int>> by_predicate_;
    std::vector<std::vector<std::vector<std::vector<int>>>> by_argument_; // pred, pos, object
    std::deque<int> queue_;
    std::unordered_set<AtomKey, AtomKeyHash> seen_instances_;
};

} // namespace

int Reachability::object_id(const std::string &name) const {
    auto it = object_ids.find(name);
    return it == object_ids.end() ? -1 : it->second;
}

int Reachability::predicate_id(const std::string &name) const {
    auto it = predicate_ids.find(name);
    return it == predicate_ids.end() ? -1 : it->second;
}

std::string Reachability::atom_name(const AtomKey &atom) const {
    std::string name = "(" + predicates[atom[0]];
    for (std::size_t i = 1; i < atom.size(); ++i)
        name += " " + objects[atom[i]];
    return name + ")";
}

Reachability explore(const pddl::Domain &domain, const pddl::Problem &problem,
                     const StopCheck &stop) {
    Reachability result;
    Explorer explorer(domain, problem, result, stop);
    explorer.run();
    return result;
}

} // namespace envdesign::ground
