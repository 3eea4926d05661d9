// Tc3_JsonXml's native part (decision 0285): the work of FB_JsonDomParser
// and FB_JsonSaxReader (stdlib/libraries/Tc3_JsonXml) over nlohmann-json.
// F_strun_Json(op, key, v, p, n, r) does one operation on the document of
// the parser instance `key` (json_documents.h); `v` is an SJsonValue or an
// iterator, `p` the address of a string (input) or of a buffer (output),
// `n` an integer argument (a value, a size, a second string's address), `r`
// a real value. F_strun_JsonReal(op, key, v) reads a number as LREAL.
// Every address is checked against the project's memory; strings read from
// it must end inside it.
#include <cmath>
#include <cstring>
#include <limits>

#include "interpreter/builtins/libraries/json_documents.h"
#include "interpreter/builtins/libraries/library_natives.h"
#include "interpreter/builtins/libraries/plc_memory_text.h"
#include "interpreter/exec/value_nodes.h"

namespace strun::stdlib::bind {

namespace {

using exec::Ctx;
using json::Json;

// The operations (E_strun_JsonOp in stdlib/libraries/Tc3_JsonXml/json_ops.st).
enum Op : int {
    kParse = 1, kNew, kRoot, kDocLength, kCopyDoc, kFindMember, kHasMember, kType, kArraySize, kArrayValueByIdx,
    kGetInt, kGetBool, kStringLength, kCopyString, kJsonLength, kCopyJson, kIs,
    kMemberBegin, kMemberEnd, kNextMember, kMemberName, kMemberValue, kArrayBegin, kArrayEnd, kNextArray, kArrayValue,
    kAddNull, kAddBool, kAddInt, kAddUint, kAddDouble, kAddString, kAddJson, kAddObject, kAddArray,
    kPushNull, kPushBool, kPushInt, kPushUint, kPushDouble, kPushString, kPushJson,
    kSetNull, kSetBool, kSetInt, kSetUint, kSetDouble, kSetString, kSetJson, kSetObject, kSetArray,
    kRemoveMember, kClearArray, kFindMemberPath,
    kGetDouble = 60,
    kSaxLoad = 70, kSaxKind, kSaxInt, kSaxString, kSaxReal,
};

// IsX tests (the `n` of kIs).
enum Test : int { kIsArray = 1, kIsBool, kIsDouble, kIsFalse, kIsInt, kIsInt64, kIsNull, kIsNumber, kIsObject, kIsString, kIsTrue, kIsUint, kIsUint64 };

// Copies `text` and its NUL to the buffer [a, a + size): its length with the
// NUL, or 0 (and an empty buffer) when it does not fit (TwinCAT's Copy* methods).
// A negative size -N: a buffer of N bytes, the text cut to fit (the Get*
// methods returning STRING(255)).
int64_t copyOut(Ctx& c, int64_t a, int64_t size, std::string_view text) {
    uint8_t* p = plcAddress(a);
    const bool cut = size < 0;
    if (cut) size = -size;
    if (!p || size <= 0 || !c.m->memory.contains(p, static_cast<size_t>(size))) return 0;
    if (cut && text.size() + 1 > static_cast<uint64_t>(size)) text = text.substr(0, static_cast<size_t>(size) - 1);
    if (text.size() + 1 > static_cast<uint64_t>(size)) {
        p[0] = 0;
        return 0;
    }
    std::memcpy(p, text.data(), text.size());
    p[text.size()] = 0;
    return static_cast<int64_t>(text.size() + 1);
}

int jsonType(const Json& j) {  // EJsonType
    switch (j.type()) {
        case Json::value_t::null: return 0;
        case Json::value_t::boolean: return j.get<bool>() ? 2 : 1;
        case Json::value_t::object: return 3;
        case Json::value_t::array: return 4;
        case Json::value_t::string: return 5;
        default: return 6;
    }
}

int64_t integerOf(const Json& j) {
    if (j.is_number_integer()) return j.get<int64_t>();  // unsigned above LINT: its bits
    if (j.is_number_float()) {
        const double d = j.get<double>();
        if (!(d > -9.3e18 && d < 9.3e18)) return 0;
        return static_cast<int64_t>(d);
    }
    if (j.is_boolean()) return j.get<bool>() ? 1 : 0;
    return 0;
}

bool test(const Json& j, int which) {
    const bool isInt = j.is_number_integer();
    const bool neg = j.is_number_integer() && !j.is_number_unsigned() && j.get<int64_t>() < 0;
    switch (which) {
        case kIsArray: return j.is_array();
        case kIsBool: return j.is_boolean();
        case kIsDouble: return j.is_number_float();
        case kIsFalse: return j.is_boolean() && !j.get<bool>();
        case kIsInt: {
            if (!isInt) return false;
            if (j.is_number_unsigned()) return j.get<uint64_t>() <= static_cast<uint64_t>(std::numeric_limits<int32_t>::max());
            const int64_t v = j.get<int64_t>();
            return v >= std::numeric_limits<int32_t>::min() && v <= std::numeric_limits<int32_t>::max();
        }
        case kIsInt64: return isInt && (!j.is_number_unsigned() || j.get<uint64_t>() <= static_cast<uint64_t>(std::numeric_limits<int64_t>::max()));
        case kIsNull: return j.is_null();
        case kIsNumber: return j.is_number();
        case kIsObject: return j.is_object();
        case kIsString: return j.is_string();
        case kIsTrue: return j.is_boolean() && j.get<bool>();
        case kIsUint: return isInt && !neg && (j.is_number_unsigned() ? j.get<uint64_t>() : static_cast<uint64_t>(j.get<int64_t>())) <= std::numeric_limits<uint32_t>::max();
        case kIsUint64: return isInt && !neg;
    }
    return false;
}

// Parses a raw JSON text for SetJson/AddJsonMember/PushbackJson.
bool parseText(std::string_view text, Json& out) {
    if (!json::nestingWithin(text)) return false;
    out = Json::parse(text, nullptr, false);
    return !out.is_discarded();
}

struct JsonOpNode final : exec::Expr {
    Expr *op, *key, *v, *p, *n, *r;
    JsonOpNode(Expr* o, Expr* k, Expr* vv, Expr* pp, Expr* nn, Expr* rr) : op(o), key(k), v(vv), p(pp), n(nn), r(rr) {}

    int64_t i(Ctx& c) override {
        const int code = static_cast<int>(op->i(c));
        const uint64_t docKey = static_cast<uint64_t>(key->i(c));
        if (docKey == 0) return 0;
        if (code >= kSaxLoad) return sax(c, code, docKey);
        json::Document& doc = json::documentFor(docKey);
        const uint64_t handle = static_cast<uint64_t>(v->i(c));
        std::string_view text;
        switch (code) {
            case kParse: {
                if (!readPlcText(c, p->i(c), text) || !json::nestingWithin(text)) { doc.reset(Json::object()); return 0; }
                Json parsed = Json::parse(text, nullptr, false);
                if (parsed.is_discarded()) { doc.reset(Json::object()); return 0; }
                doc.reset(std::move(parsed));
                return static_cast<int64_t>(doc.handleOf(Json::json_pointer()));
            }
            case kNew:
                doc.reset(Json::object());
                return static_cast<int64_t>(doc.handleOf(Json::json_pointer()));
            case kRoot: return static_cast<int64_t>(doc.handleOf(Json::json_pointer()));
            case kDocLength: return static_cast<int64_t>(json::print(doc.root).size());
            case kCopyDoc: return copyOut(c, p->i(c), n->i(c), json::print(doc.root));
            case kMemberBegin:
            case kMemberEnd:
            case kArrayBegin:
            case kArrayEnd: {
                Json* j = doc.resolve(handle);
                const bool members = code == kMemberBegin || code == kMemberEnd;
                if (!j || (members ? !j->is_object() : !j->is_array())) return 0;
                const bool end = code == kMemberEnd || code == kArrayEnd;
                return static_cast<int64_t>(doc.iterator(handle, end ? j->size() : 0));
            }
            case kNextMember:
            case kNextArray: {
                uint64_t container = 0, position = 0;
                if (!doc.splitIterator(handle, container, position)) return 0;
                Json* j = doc.resolve(container);
                if (!j || position >= j->size()) return static_cast<int64_t>(handle);
                return static_cast<int64_t>(doc.iterator(container, position + 1));
            }
            case kMemberName:
            case kMemberValue:
            case kArrayValue: {
                uint64_t container = 0, position = 0;
                if (!doc.splitIterator(handle, container, position)) return 0;
                Json* j = doc.resolve(container);
                const Json::json_pointer* path = doc.pathOf(container);
                if (!j || !path || position >= j->size()) return 0;
                if (code == kArrayValue) {
                    if (!j->is_array()) return 0;
                    return static_cast<int64_t>(doc.handleOf(*path / position));
                }
                if (!j->is_object()) return 0;
                auto it = std::next(j->begin(), static_cast<std::ptrdiff_t>(position));
                if (code == kMemberName) return copyOut(c, p->i(c), n->i(c), it.key());
                return static_cast<int64_t>(doc.handleOf(*path / it.key()));
            }
            default: break;
        }
        Json* j = doc.resolve(handle);
        if (!j) return 0;
        const Json::json_pointer* path = doc.pathOf(handle);
        auto member = [&](Json value) -> int64_t {
            // AddXMember: adds (or replaces) `name` in the object v; the new member's handle.
            if (!j->is_object() || !readPlcText(c, p->i(c), text)) return 0;
            std::string name(text);
            (*j)[name] = std::move(value);
            return static_cast<int64_t>(doc.handleOf(*path / name));
        };
        auto push = [&](Json value) -> int64_t {
            if (!j->is_array()) return 0;
            j->push_back(std::move(value));
            return static_cast<int64_t>(doc.handleOf(*path / (j->size() - 1)));
        };
        auto set = [&](Json value) -> int64_t {
            *j = std::move(value);
            return static_cast<int64_t>(handle);
        };
        auto stringArg = [&](Expr* e, std::string& out) {
            if (!readPlcText(c, e->i(c), text)) return false;
            out.assign(text);
            return true;
        };
        std::string s;
        Json raw;
        switch (code) {
            case kFindMember:
            case kHasMember: {
                if (!j->is_object() || !readPlcText(c, p->i(c), text)) return 0;
                auto it = j->find(std::string(text));
                if (it == j->end()) return 0;
                return code == kHasMember ? 1 : static_cast<int64_t>(doc.handleOf(*path / std::string(text)));
            }
            case kFindMemberPath: {
                // "a/b/c": members below v (TwinCAT's FindMemberPath).
                if (!readPlcText(c, p->i(c), text)) return 0;
                Json::json_pointer at = *path;
                Json* cur = j;
                size_t start = 0;
                while (start <= text.size()) {
                    size_t end = text.find('/', start);
                    if (end == std::string_view::npos) end = text.size();
                    std::string name(text.substr(start, end - start));
                    if (!cur->is_object()) return 0;
                    auto it = cur->find(name);
                    if (it == cur->end()) return 0;
                    cur = &*it;
                    at /= name;
                    start = end + 1;
                }
                return static_cast<int64_t>(doc.handleOf(at));
            }
            case kType: return jsonType(*j);
            case kArraySize: return j->is_array() ? static_cast<int64_t>(j->size()) : 0;
            case kArrayValueByIdx: {
                const int64_t index = n->i(c);
                if (!j->is_array() || index < 0 || static_cast<uint64_t>(index) >= j->size()) return 0;
                return static_cast<int64_t>(doc.handleOf(*path / static_cast<size_t>(index)));
            }
            case kGetInt: return integerOf(*j);
            case kGetBool: return j->is_boolean() && j->get<bool>() ? 1 : 0;
            case kStringLength: return j->is_string() ? static_cast<int64_t>(j->get_ref<const std::string&>().size()) : 0;
            case kCopyString: return j->is_string() ? copyOut(c, p->i(c), n->i(c), j->get_ref<const std::string&>()) : 0;
            case kJsonLength: return static_cast<int64_t>(json::print(*j).size());
            case kCopyJson: return copyOut(c, p->i(c), n->i(c), json::print(*j));
            case kIs: return test(*j, static_cast<int>(n->i(c))) ? 1 : 0;
            case kAddNull: return member(Json());
            case kAddBool: return member(Json(n->i(c) != 0));
            case kAddInt: return member(Json(n->i(c)));
            case kAddUint: return member(Json(static_cast<uint64_t>(n->i(c))));
            case kAddDouble: return member(Json(r->f(c)));
            case kAddString: return stringArg(n, s) ? member(Json(s)) : 0;
            case kAddJson: return stringArg(n, s) && parseText(s, raw) ? member(std::move(raw)) : 0;
            case kAddObject: return member(Json::object());
            case kAddArray: return member(Json::array());
            case kPushNull: return push(Json());
            case kPushBool: return push(Json(n->i(c) != 0));
            case kPushInt: return push(Json(n->i(c)));
            case kPushUint: return push(Json(static_cast<uint64_t>(n->i(c))));
            case kPushDouble: return push(Json(r->f(c)));
            case kPushString: return stringArg(p, s) ? push(Json(s)) : 0;
            case kPushJson: return stringArg(p, s) && parseText(s, raw) ? push(std::move(raw)) : 0;
            case kSetNull: return set(Json());
            case kSetBool: return set(Json(n->i(c) != 0));
            case kSetInt: return set(Json(n->i(c)));
            case kSetUint: return set(Json(static_cast<uint64_t>(n->i(c))));
            case kSetDouble: return set(Json(r->f(c)));
            case kSetString: return stringArg(p, s) ? set(Json(s)) : 0;
            case kSetJson: return stringArg(p, s) && parseText(s, raw) ? set(std::move(raw)) : 0;
            case kSetObject: return set(Json::object());
            case kSetArray: return set(Json::array());
            case kRemoveMember: {
                if (!j->is_object() || !readPlcText(c, p->i(c), text)) return 0;
                return j->erase(std::string(text)) ? 1 : 0;
            }
            case kClearArray:
                if (!j->is_array()) return 0;
                j->clear();
                return 1;
            default: return 0;
        }
    }

    // FB_JsonSaxReader: the events of one document, read one by one.
    int64_t sax(Ctx& c, int code, uint64_t docKey) {
        std::vector<json::SaxEvent>& events = json::saxEventsFor(docKey);
        if (code == kSaxLoad) {
            std::string_view text;
            if (!readPlcText(c, p->i(c), text) || !json::saxEvents(text, events)) return -1;
            return static_cast<int64_t>(events.size());
        }
        const int64_t index = n->i(c);
        if (index < 0 || static_cast<uint64_t>(index) >= events.size()) return 0;
        const json::SaxEvent& e = events[static_cast<size_t>(index)];
        switch (code) {
            case kSaxKind: return e.kind;
            case kSaxInt: return e.integer;
            case kSaxString: return copyOut(c, p->i(c), -static_cast<int64_t>(v->i(c) & 0xFFFFFF), e.text) ? static_cast<int64_t>(e.text.size()) : -1;
            default: return 0;
        }
    }

    double f(Ctx& c) override {
        const int code = static_cast<int>(op->i(c));
        const uint64_t docKey = static_cast<uint64_t>(key->i(c));
        if (docKey == 0) return 0;
        if (code == kSaxReal) {
            std::vector<json::SaxEvent>& events = json::saxEventsFor(docKey);
            const int64_t index = static_cast<int64_t>(v->i(c));
            if (index < 0 || static_cast<uint64_t>(index) >= events.size()) return 0;
            return events[static_cast<size_t>(index)].real;
        }
        Json* j = json::documentFor(docKey).resolve(static_cast<uint64_t>(v->i(c)));
        if (!j || !j->is_number()) return 0;
        return j->get<double>();
    }
};

Checked argAs(Checker& ck, const Checked& a, TK kind, const std::string& fn) {
    if (!a.ok) return a;
    // An address (ADR(...), a POINTER) goes to the integer slots as it is.
    if ((kind == TK::ULInt || kind == TK::LInt) && a.type && a.type->kind == TK::Pointer) return a;
    return ck.coerce(a, ck.types().elementary(kind), a.loc, fn.c_str());
}

}  // namespace

void registerTc3JsonXmlNatives(Checker& ck) {
    ck.addBuiltin("F_STRUN_JSON", [](Checker& ck, CallArgs& call) -> Checked {
        std::vector<Checked> a;
        if (!bindFixed(ck, call, {{"OP"}, {"KEY"}, {"V"}, {"P"}, {"N"}, {"R"}}, a)) return ck.bad(call.loc);
        const TK kinds[6] = {TK::DInt, TK::ULInt, TK::ULInt, TK::ULInt, TK::LInt, TK::LReal};
        exec::Expr* nodes[6];
        for (int k = 0; k < 6; ++k) {
            Checked v = argAs(ck, a[k], kinds[k], call.name);
            if (!v.ok) return v;
            nodes[k] = v.node;
        }
        auto* node = ck.pool().make<JsonOpNode>(nodes[0], nodes[1], nodes[2], nodes[3], nodes[4], nodes[5]);
        return makeResult(ck, node, ck.types().elementary(TK::LInt), call, a, false);
    });
    ck.addBuiltin("F_STRUN_JSONREAL", [](Checker& ck, CallArgs& call) -> Checked {
        std::vector<Checked> a;
        if (!bindFixed(ck, call, {{"OP"}, {"KEY"}, {"V"}}, a)) return ck.bad(call.loc);
        Checked op = argAs(ck, a[0], TK::DInt, call.name);
        Checked key = argAs(ck, a[1], TK::ULInt, call.name);
        Checked v = argAs(ck, a[2], TK::ULInt, call.name);
        if (!op.ok || !key.ok || !v.ok) return ck.bad(call.loc);
        auto* node = ck.pool().make<JsonOpNode>(op.node, key.node, v.node, v.node, v.node, v.node);
        return makeResult(ck, node, ck.types().elementary(TK::LReal), call, a, false);
    });
    registerTc3JsonSymbolNatives(ck);
}

}  // namespace strun::stdlib::bind
