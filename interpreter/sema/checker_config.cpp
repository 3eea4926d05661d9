// CONFIGURATION / RESOURCE / TASK / PROGRAM ... WITH: program instances and
// the tasks that run them; or, without a CONFIGURATION, the contract's
// default: every PROGRAM in one freewheeling MainTask.
#include <algorithm>
#include <cctype>
#include <cstring>

#include <fmt/format.h>

#include "interpreter/sema/checker.h"
#include "interpreter/sema/fb_eno_slots.h"
#include "interpreter/sema/node_factory.h"
#include "interpreter/source/twincat_tasks.h"
#include "runtime/plc_profile.h"
#include "runtime/task_rules.h"
#include "stdlib/library_registry.h"
#include "stdlib/time_literals.h"

namespace strun::sema {

void Checker::instantiateProgram(const std::string& name, PouInfo* pou, const ast::Loc& loc) {
    layoutPou(pou);
    if (!programIndex_.try_emplace(upper(name), model_.programs.size()).second) {
        error(diag::E0106, loc, fmt::format("duplicate program instance '{}'", name));
        return;
    }
    ProgramInstance inst;
    inst.name = name;
    inst.pou = pou;
    inst.loc = loc;
    size_t size = pou->instanceType ? pou->instanceType->size : 8;
    inst.memory = model_.allocate(size);
    if (!pou->instanceInit.empty()) std::memcpy(inst.memory, pou->instanceInit.data(), std::min(size, pou->instanceInit.size()));
    model_.programs.push_back(std::move(inst));
}

void Checker::buildDefaultConfiguration() {
    ConfiguredTask task;
    task.spec.name = "MainTask";
    task.spec.kind = rt::TaskKind::Freewheeling;
    task.spec.priority = 30;
    task.spec.watchdog = rt::defaultProfile().defaultMainWatchdog;
    // On a family with fixed tasks the default MainTask plays the first one's
    // role (M340: MAST), with its priority and default watchdog (%SW11 reads
    // 250); it keeps the contract's name (decision 0245).
    if (!profile().fixedTasks.empty()) {
        const rt::FixedTask& first = profile().fixedTasks.front();
        task.spec.systemSlot = 0;
        task.spec.priority = first.priority;
        task.spec.watchdog = first.defaultWatchdog;
    }
    // A family with a scan program (XGI): the lone programs are that scan
    // program, at its priority below every task (decision 0245).
    if (profile().triggerSampling == rt::TriggerSampling::EndOfScan) {
        task.spec.isScanProgram = true;
        task.spec.priority = profile().unassignedTaskPriority;
    }
    for (PouInfo* p : pouOrder_) {
        if (p->kind != ast::PouKind::Program || libraryFiles_.count(p->ast->loc.file)) continue;
        instantiateProgram(p->name, p, p->ast->loc);
    }
    for (auto& inst : model_.programs) task.calls.push_back({&inst, inst.pou->code, inst.memory, inst.name});
    model_.tasks.push_back(std::move(task));
}

void Checker::buildConfiguration() {
    if (configurations_.empty()) {
        buildDefaultConfiguration();
        return;
    }
    // The task objects (.TcTTO) of a TwinCAT project each bring a configuration
    // of this name: together they are the project's one (decision 0144).
    auto fromTaskObject = [](const ast::Configuration* c) { return c->name == source::kTwinCatTasksConfiguration; };
    const bool taskObjectsOnly = std::all_of(configurations_.begin(), configurations_.end(), fromTaskObject);
    if (configurations_.size() > 1 && !taskObjectsOnly) {
        auto& d = error(diag::E0601, configurations_[1]->loc, "only one CONFIGURATION per project");
        if (std::any_of(configurations_.begin(), configurations_.end(), fromTaskObject))
            d.withHelp("a TwinCAT project's tasks come from its .TcTTO files; remove them or the CONFIGURATION");
    }
    std::vector<const ast::TaskDecl*> taskDecls;
    std::vector<const ast::ProgramConfig*> programDecls;
    for (size_t k = 0; k < (taskObjectsOnly ? configurations_.size() : 1); ++k) {
        ast::Configuration& conf = *configurations_[k];
        for (auto& t : conf.tasks) taskDecls.push_back(&t);
        for (auto& p : conf.programs) programDecls.push_back(&p);
        for (auto& r : conf.resources) {
            for (auto& t : r.tasks) taskDecls.push_back(&t);
            for (auto& p : r.programs) programDecls.push_back(&p);
        }
    }
    // Tasks
    auto constTime = [&](const ast::Expr* e, rt::PlcTime& out) {
        // T#500us, T#1500us: a literal keeps its microseconds (a TIME value
        // counts milliseconds; the task period is in nanoseconds).
        if (e->kind == ast::ExprKind::Literal && e->lit == ast::LitKind::Duration)
            if (auto ns = stdlib::parseDurationLiteral(e->text); ns && ns.value() >= 0) {
                out = ns.value();
                return true;
            }
        Checked c = checkExpr(*e);
        if (!c.ok) return false;
        if (!c.isConst || !isTimeLike(c.type->kind)) {
            error(diag::E0601, e->loc, "expected a constant duration such as T#10ms");
            return false;
        }
        out = c.type->kind == TK::Time ? c.constInt * 1000000 : c.constInt;
        return true;
    };
    auto boolRef = [&](const ast::Expr* e, rt::BoolRef& out) {
        Checked c = checkExpr(*e);
        if (!c.ok) return false;
        if (c.type->kind != TK::Bool || !c.isPlace || c.direct != Checked::Direct::Abs) {
            if (c.type->kind == TK::Bool && c.node->bitIndex() >= 0) {
                auto* bp = exec::nodeCast<exec::BitPlace<uint8_t>>(c.node);
                exec::Ctx dummy;
                out.byte = bp->base->addr(dummy);
                out.bit = bp->bit;
                return true;
            }
            error(diag::E0601, e->loc, "expected a global BOOL variable");
            return false;
        }
        out.byte = c.directAbs + c.directOffset;
        out.bit = -1;
        return true;
    };
    for (const ast::TaskDecl* td : taskDecls) {
        ConfiguredTask task;
        rt::TaskSpec& s = task.spec;
        s.name = td->name;
        s.loc = td->loc;
        s.kind = rt::TaskKind::Freewheeling;
        s.priority = 30;
        bool hasInterval = false;
        bool watchdogOn = false;
        for (const auto& p : td->params) {
            std::string key = upper(p.name);
            if (!p.value) continue;
            const std::string word = p.value->kind == ast::ExprKind::Literal ? upper(p.value->text) : "";
            if (key == "INTERVAL" && (word == "TRUE" || word == "FALSE")) {
                // INTERVAL := TRUE: a cyclic task with the target's default cycle
                // time, as the IDE creates one (Baosky: 20 ms; decision 0297).
                if (word == "TRUE" && profile().defaultCyclicInterval > 0) {
                    s.interval = profile().defaultCyclicInterval;
                    hasInterval = true;
                } else {
                    error(diag::E0601, p.value->loc, fmt::format("INTERVAL := {} of task '{}': {}; write the cycle time (INTERVAL := T#20ms)", word, s.name,
                                                    word == "FALSE" ? "an INTERVAL is a time"
                                                                    : fmt::format("{} has no default cycle time for a cyclic task", profile().description)));
                }
                s.intervalGiven = true;
            } else if (key == "INTERVAL") {
                rt::PlcTime t = 0;
                if (constTime(p.value.get(), t)) {
                    s.interval = t;
                    hasInterval = t > 0;
                    if (t <= 0)
                        warning(diag::W0015, p.value->loc, fmt::format("the INTERVAL of task '{}' is {}: not a period, the task runs freewheeling "
                                                          "(again and again without pause)", s.name, t == 0 ? "zero" : "negative"));
                }
                s.intervalGiven = true;
            } else if (key == "PRIORITY") {
                int64_t v = 0;
                if (constIntExpr(p.value.get(), v, "PRIORITY")) s.priority = static_cast<int>(std::clamp<int64_t>(v, -1000000, 1000000));
                s.priorityGiven = true;
            } else if (key == "WATCHDOG") {
                // WATCHDOG := TRUE: "check Watchdog" without a time, the seed's
                // default applies (below); FALSE: no watchdog (decision 0244).
                if (word == "TRUE" || word == "FALSE") {
                    watchdogOn = word == "TRUE";
                    s.watchdog = 0;
                } else {
                    constTime(p.value.get(), s.watchdog);
                }
                s.watchdogGiven = true;
            } else if (key == "EXTERNAL") {
                // An external task also when its input is wrong: one message for
                // the bad address, not a second one for a task without INTERVAL.
                externalInput(*p.value, s);
                s.kind = rt::TaskKind::External;
            } else if (key == "INPUT_DELAY") {
                constTime(p.value.get(), s.inputDelay);
                s.inputDelayGiven = true;
            } else if (key == "EDGE") {
                std::string v = p.value->kind == ast::ExprKind::Name ? upper(p.value->name) : "";
                if (v == "RISING") s.edges = rt::kEdgeRising;
                else if (v == "FALLING") s.edges = rt::kEdgeFalling;
                else if (v == "BOTH") s.edges = rt::kEdgeBoth;
                else error(diag::E0601, p.value->loc, "EDGE must be RISING, FALLING or BOTH");
            } else if (key == "SINGLE" || key == "STATUS") {
                if (boolRef(p.value.get(), s.trigger)) s.kind = key == "SINGLE" ? rt::TaskKind::Event : rt::TaskKind::Status;
            } else if (key == "EVENT") {
                std::string v = p.value->kind == ast::ExprKind::Name ? upper(p.value->name) : "";
                if (v == "STARTUP") s.kind = rt::TaskKind::Startup;
                else if (v == "PROGRAM_ERROR") s.kind = rt::TaskKind::ProgramError;
                else if (v == "EXEC_TIMEOUT") s.kind = rt::TaskKind::ExecTimeout;
                else if (boolRef(p.value.get(), s.trigger)) s.kind = rt::TaskKind::Event;
            } else if (key == "AT") {
                Checked c = checkExpr(*p.value);
                if (c.ok && c.isConst && (c.type->kind == TK::Dt || c.type->kind == TK::LDt)) {
                    s.kind = rt::TaskKind::TimeEvent;
                    s.atCalendarNanos = c.type->kind == TK::Dt ? c.constInt * 1000000000 : c.constInt;
                } else if (c.ok) {
                    error(diag::E0601, p.value->loc, "AT needs a date-and-time literal such as DT#2026-01-01-02:00:00");
                }
            } else if (key == "REPEAT") {
                std::string v = p.value->kind == ast::ExprKind::Name ? upper(p.value->name) : "";
                static const std::map<std::string, rt::TimeRepeat> repeats = {
                    {"HOURLY", rt::TimeRepeat::Hourly}, {"DAILY", rt::TimeRepeat::Daily}, {"WEEKLY", rt::TimeRepeat::Weekly},
                    {"MONTHLY", rt::TimeRepeat::Monthly}, {"MONTH_END", rt::TimeRepeat::MonthEnd}, {"YEARLY", rt::TimeRepeat::Yearly},
                    {"ONCE", rt::TimeRepeat::Once}};
                auto it = repeats.find(v);
                if (it == repeats.end()) error(diag::E0601, p.value->loc, "REPEAT must be HOURLY, DAILY, WEEKLY, MONTHLY, MONTH_END or YEARLY");
                else s.repeat = it->second;
            } else {
                error(diag::E0601, p.loc, fmt::format("unknown task parameter '{}'", p.name));
            }
        }
        if (hasInterval && s.kind == rt::TaskKind::Freewheeling) s.kind = rt::TaskKind::Cyclic;
        if (watchdogOn) {
            // Seed 000: a cyclic task's default watchdog is twice its period (at
            // most the target's largest watchdog); every other kind's is 200 ms.
            s.watchdog = s.kind == rt::TaskKind::Cyclic ? 2 * s.interval : 200 * rt::kMillisecond;
            if (profile().maxWatchdog > 0) s.watchdog = std::min(s.watchdog, profile().maxWatchdog);
        }
        if (std::string warning = rt::applyTaskDefaults(profile(), s); !warning.empty()) log_.warning(diag::W0007, s.loc, warning);
        model_.tasks.push_back(std::move(task));
    }
    std::vector<rt::TaskSpec> specs;
    for (auto& t : model_.tasks) specs.push_back(t.spec);
    for (const auto& v : rt::checkTaskRules(profile(), specs)) error(v.unavailableOnTarget ? diag::E0602 : diag::E0601, v.loc, v.message);
    // Indices, not pointers: the unassigned-program task below is added to model_.tasks.
    std::unordered_map<std::string, size_t> taskByName;  // the first of a name, as a scan finds it
    for (size_t i = 0; i < model_.tasks.size(); ++i) taskByName.try_emplace(upper(model_.tasks[i].spec.name), i);
    auto findTask = [&](const std::string& name) -> ConfiguredTask* {
        auto it = taskByName.find(upper(name));
        return it == taskByName.end() ? nullptr : &model_.tasks[it->second];
    };
    // Program instances and FB bindings
    for (const ast::ProgramConfig* pc : programDecls) {
        ConfiguredTask* task = nullptr;
        if (!pc->task.empty()) {
            task = findTask(pc->task);
            if (!task) {
                error(diag::E0601, pc->loc, fmt::format("unknown task '{}'", pc->task));
                continue;
            }
        } else {
            task = findTask(std::string(profile().unassignedTaskName));
            if (!task) {
                // IEC: a program with no task runs cyclically at the lowest priority.
                ConfiguredTask dt;
                dt.spec.name = std::string(profile().unassignedTaskName);
                dt.spec.loc = pc->loc;
                dt.spec.kind = rt::TaskKind::Freewheeling;
                dt.spec.priority = profile().unassignedTaskPriority;
                dt.spec.isScanProgram = true;
                model_.tasks.push_back(std::move(dt));
                taskByName.try_emplace(upper(model_.tasks.back().spec.name), model_.tasks.size() - 1);
                task = &model_.tasks.back();
            }
        }
        if (!pc->isProgram) {
            VarSym* g = lookupVar(upper(pc->instance));
            if (!g || g->type->kind != TK::FunctionBlock || g->storage != Storage::Abs) {
                error(diag::E0107, pc->loc, fmt::format("'{}' is not a global function-block instance", pc->instance));
                continue;
            }
            g->used = true;
            task->calls.push_back({nullptr, g->type->pou->code, g->abs, pc->instance});
            continue;
        }
        auto it = pous_.find(scopedKey(upper(pc->typeName)));
        if (it == pous_.end() || it->second->kind != ast::PouKind::Program) {
            error(diag::E0107, pc->loc, fmt::format("'{}' is not a PROGRAM", pc->typeName));
            continue;
        }
        instantiateProgram(pc->instance, it->second, pc->loc);
        ProgramInstance& inst = model_.programs.back();
        if (upper(inst.name) != upper(pc->instance)) continue;
        // Parameter connections: evaluated in the configuration's scope each activation.
        Checked self;
        self.ok = true;
        self.loc = pc->loc;
        self.type = inst.pou->instanceType;
        self.isPlace = true;
        self.direct = Checked::Direct::Abs;
        self.directAbs = inst.memory;
        self.node = pool().make<exec::AbsVar<void>>(inst.memory);
        model_.names.push_back(inst.name);
        currentPouName_ = &model_.names.back();
        for (const auto& a : pc->args) {
            if (!a.value) continue;
            Checked member = memberOf(self, a.name, a.loc);
            if (!member.ok) continue;
            member.readOnly = false;
            if (a.output) {
                Checked target = checkExpr(*a.value);
                if (!target.ok) continue;
                if (exec::Stmt* st = assignChecked(target, member, a.loc)) inst.after.push_back(st);
            } else {
                Checked v = checkExpr(*a.value);
                if (!v.ok) continue;
                if (exec::Stmt* st = assignChecked(member, v, a.loc)) inst.before.push_back(st);
            }
        }
        currentPouName_ = nullptr;
        task->calls.push_back({&inst, inst.pou->code, inst.memory, inst.name});
    }
    // TwinCAT: every PROGRAM has its instance, named after it, whether a task
    // calls it or not; one that no task calls runs only when a POU calls it.
    if (taskObjectsOnly)
        for (PouInfo* p : pouOrder_) {
            if (p->kind != ast::PouKind::Program || libraryFiles_.count(p->ast->loc.file)) continue;
            const std::string key = upper(p->name);
            // The test runner's program gets its one instance from addTestProgram.
            if (!options_.testProgram.empty() && key == upper(options_.testProgram)) continue;
            if (!findProgram(key)) instantiateProgram(p->name, p, p->ast->loc);
        }
    if (!options_.testProgram.empty()) addTestProgram(options_.testProgram);
    for (const auto& t : model_.tasks)
        if (std::string problem = rt::programCountProblem(profile(), t.spec, int(t.calls.size())); !problem.empty())
            error(diag::E0601, t.spec.loc, problem);
}

// The test runner's PROGRAM in a project with a CONFIGURATION (decision 0141):
// one instance, called last by the first cyclic or freewheeling task declared,
// or else by the target's task for programs without one.
void Checker::addTestProgram(const std::string& name) {
    auto it = pous_.find(scopedKey(upper(name)));
    if (it == pous_.end() || it->second->kind != ast::PouKind::Program) return;
    ConfiguredTask* host = nullptr;
    for (auto& t : model_.tasks)
        if (t.spec.kind == rt::TaskKind::Cyclic || t.spec.kind == rt::TaskKind::Freewheeling) {
            host = &t;
            break;
        }
    if (!host) {
        ConfiguredTask dt;
        dt.spec.name = std::string(profile().unassignedTaskName);
        dt.spec.loc = it->second->ast->loc;
        dt.spec.kind = rt::TaskKind::Freewheeling;
        dt.spec.priority = profile().unassignedTaskPriority;
        dt.spec.isScanProgram = true;
        model_.tasks.push_back(std::move(dt));
        host = &model_.tasks.back();
    }
    instantiateProgram(name, it->second, it->second->ast->loc);
    ProgramInstance& inst = model_.programs.back();
    host->calls.push_back({&inst, inst.pou->code, inst.memory, inst.name});
}

// EXTERNAL := FI0 (a target's input alias) or %IX0.0 (a bit of the physical inputs).
bool Checker::externalInput(const ast::Expr& value, rt::TaskSpec& spec) {
    if (value.kind != ast::ExprKind::Name) {
        error(diag::E0601, value.loc, "EXTERNAL needs an input bit such as %IX0.0 or an input name of the target");
        return false;
    }
    if (!value.name.empty() && value.name[0] == '%') {
        std::string key = upper(value.name);
        if (key.size() < 3 || key[1] != 'I' || (std::isalpha(static_cast<unsigned char>(key[2])) && key[2] != 'X')) {
            error(diag::E0601, value.loc, fmt::format("EXTERNAL needs an input bit (%IX...), not '{}'", value.name));
            return false;
        }
        int bit = -1;
        uint8_t* p = mapAddress(value.name, types().elementary(TK::Bool), value.loc, bit);
        if (!p) return false;
        spec.inputByte = static_cast<uint32_t>(p - model_.machine.image.inputs.data());
        spec.inputBit = bit;
        return true;
    }
    if (auto alias = rt::findInputAlias(profile(), value.name)) {
        spec.inputByte = alias->byte;
        spec.inputBit = alias->bit;
        return true;
    }
    std::string names;
    for (const auto& a : profile().inputAliases) names += (names.empty() ? "" : ", ") + std::string(a.name);
    error(diag::E0601, value.loc, names.empty() ? fmt::format("unknown input '{}': {} has no named inputs; use an address such as %IX0.0",
                                                 value.name, profile().description)
                                   : fmt::format("unknown input '{}': the inputs of {} are {}, or an address such as %IX0.0",
                                                 value.name, profile().description, names));
    return false;
}

// ---------------------------------------------------------------- driver

void Checker::run(std::vector<ast::CompilationUnit>& units) {
    // Library names code writes in front of standard blocks and functions
    // (Tc2_Standard.TON, Tc2_System.MEMCPY): strun's library answers to them,
    // for every library of the registry (decision 0220).
    namespaces_.insert("STANDARD");
    for (const stdlib::LibraryInfo& library : stdlib::libraries()) namespaces_.insert(upper(std::string(library.name)));
    noteOverloads(units);
    noteContestedNames(units);
    addGlobalFbEnoSlots(units);  // the ENO of global instances called with EN/ENO (decision 0370)
    for (auto& u : units) collect(u);
    breakInheritanceCycles();
    // Types and enumerations first, so that enumeration values are known everywhere.
    for (auto& [key, decl] : typeDecls_) resolveTypeDecl(key, decl->loc);
    declareGlobals();
    // By index: laying out a POU may declare a specialisation of a generic block (appended).
    for (size_t i = 0; i < pouOrder_.size(); ++i)
        if (pouOrder_[i]->kind != ast::PouKind::Interface) layoutPou(pouOrder_[i]);
    buildClasses();
    buildConfiguration();
    sizeTaskInfoToTasks();
    checkBodies();
    if (log_.hasErrors()) return;
    inlineLeafCalls();
    writeAllInstancePaths();
    buildFbInitCalls();
    warnUnused();
}

// A TcUnit suite instance (a block extending FB_TestSuite, or an array of
// them) is used by RUN(), which names no variable.
static bool isTestSuiteInstance(const Type* t) {
    while (t && t->kind == TK::Array) t = t->elem;
    if (!t || t->kind != TK::FunctionBlock || !t->pou) return false;
    for (const PouInfo* p = t->pou->parent; p; p = p->parent)
        if (upper(p->name) == "FB_TESTSUITE") return true;
    return false;
}

void Checker::warnUnused() {
    for (PouInfo* p : pouOrder_) {
        if (libraryFiles_.count(p->ast->loc.file)) continue;
        if (isSpecialisation(p)) continue;  // warned on the generic block itself
        auto visit = [&](PouInfo* pou) {
            for (auto& v : pou->ownedVars) {
                if (v->used || v.get() == pou->result || constantsUsedEarly_.count({pou, upper(v->name)})) continue;
                if (v->section == ast::VarSection::Var || v->section == ast::VarSection::Temp) {
                    if (isTestSuiteInstance(v->type)) continue;  // RUN() of strun test calls it
                    // Program variables are visible in --dump, but a block instance nobody calls does nothing.
                    if (pou->kind == ast::PouKind::Program) {
                        if (v->type && v->type->kind == TK::FunctionBlock)
                            log_.warning(diag::W0014, v->loc, fmt::format("function block instance '{}' is never called or used", v->name));
                        continue;
                    }
                    log_.warning(diag::W0003, v->loc, fmt::format("variable '{}' is never used", v->name));
                }
            }
        };
        visit(p);
        for (auto& [n, m] : p->methods) visit(m);
    }
}

}  // namespace strun::sema
