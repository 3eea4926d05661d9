#include "interpreter/sema/types.h"

#include <algorithm>
#include <cctype>

namespace strun::sema {

// ASCII only, which is what std::toupper does in the C locale strun never
// leaves, without a locale call per character (a third of the cost of a
// one-line run's name handling, decision 0156).
void upperInPlace(std::string& s) {
    for (char& c : s)
        if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
}

std::string upper(std::string s) {
    upperInPlace(s);
    return s;
}

namespace {
// `name` folded to upper case equals `upperName`, without building the folded copy.
bool equalsFolded(const std::string& name, const std::string& upperName) {
    if (name.size() != upperName.size()) return false;
    for (size_t k = 0; k < name.size(); ++k) {
        char c = name[k];
        if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
        if (c != upperName[k]) return false;
    }
    return true;
}
constexpr size_t kScannedNames = 8;  // up to this many, a scan costs less than building the index
}  // namespace

template <class T>
const T* Type::findIn(const std::vector<T>& items, NameIndex& index, const std::string& upperName) {
    if (items.size() <= kScannedNames) {
        for (const T& item : items)
            if (equalsFolded(item.name, upperName)) return &item;
        return nullptr;
    }
    if (index.data != static_cast<const void*>(items.data()) || index.size > items.size()) {
        index.positions.clear();  // replaced or reallocated: positions are kept, but so few rebuilds cost O(n) in all
        index.size = 0;
        index.data = items.data();
    }
    for (; index.size < items.size(); ++index.size) index.positions.try_emplace(upper(items[index.size].name), uint32_t(index.size));
    auto it = index.positions.find(upperName);
    return it == index.positions.end() ? nullptr : &items[it->second];
}

const Field* Type::findField(const std::string& upperName) const {
    for (const Type* t = this; t; t = t->parent)
        if (const Field* f = findIn(t->fields, t->fieldIndex_, upperName)) return f;
    return nullptr;
}

const Enumerator* Type::findEnumerator(const std::string& upperName) const { return findIn(enumerators, enumIndex_, upperName); }

bool isInteger(TK k) { return k >= TK::SInt && k <= TK::ULInt; }
bool isSignedInt(TK k) { return k >= TK::SInt && k <= TK::LInt; }
bool isUnsignedInt(TK k) { return k >= TK::USInt && k <= TK::ULInt; }
bool isBitString(TK k) { return k >= TK::Byte && k <= TK::LWord; }
bool isAnyBit(TK k) { return k == TK::Bool || isBitString(k); }
bool isReal(TK k) { return k == TK::Real || k == TK::LReal; }
bool isNumeric(TK k) { return isInteger(k) || isReal(k); }
bool isTimeLike(TK k) { return k == TK::Time || k == TK::LTime; }
bool isDateLike(TK k) { return k >= TK::Date && k <= TK::LDt; }
bool isStringType(TK k) { return k == TK::String || k == TK::WString; }
bool isCharType(TK k) { return k == TK::Char || k == TK::WChar; }
bool isElementary(TK k) { return k <= TK::WString; }

int bitWidth(TK k) {
    switch (k) {
        case TK::Bool: return 1;
        case TK::SInt: case TK::USInt: case TK::Byte: case TK::Char: return 8;
        case TK::Int: case TK::UInt: case TK::Word: case TK::WChar: return 16;
        case TK::DInt: case TK::UDInt: case TK::DWord: case TK::Real: case TK::Time:
        case TK::Date: case TK::Tod: case TK::Dt: return 32;
        default: return 64;
    }
}

int64_t nanosPerUnit(TK k) {
    switch (k) {
        case TK::Time: case TK::Tod: return 1000000;
        case TK::Date: case TK::Dt: return 1000000000;
        default: return 1;
    }
}

void TypeTable::setDefaultStringLength(uint32_t maxLen) {
    for (const bool wide : {false, true}) {
        Type* t = const_cast<Type*>(elementary(wide ? TK::WString : TK::String));
        strings_.erase({t->maxLen, wide});
        t->maxLen = maxLen;
        t->size = (maxLen + 1) * (wide ? 2 : 1);
        strings_[{maxLen, wide}] = t;
    }
}

void TypeTable::makeDurationsUnsigned() {
    for (Type& t : storage_)
        if (&t == elementary(TK::LTime) || &t == elementary(TK::Time)) t.unsignedDuration = true;
}

TK integerView(TK k) {
    switch (k) {
        case TK::Byte: case TK::Char: return TK::USInt;
        case TK::Word: case TK::WChar: return TK::UInt;
        case TK::DWord: case TK::Date: case TK::Tod: case TK::Dt: return TK::UDInt;
        case TK::LWord: return TK::ULInt;
        case TK::Time: return TK::DInt;
        case TK::LTime: case TK::LDate: case TK::LTod: case TK::LDt: return TK::LInt;
        case TK::Bool: return TK::USInt;
        default: return k;
    }
}

bool isIntRep(const Type* t) {
    TK k = t->kind;
    return k == TK::Bool || isInteger(k) || isBitString(k) || isTimeLike(k) || isDateLike(k) || isCharType(k) ||
           k == TK::Enum;
}
bool isRealRep(const Type* t) { return isReal(t->kind); }
bool isAggregate(const Type* t) {
    TK k = t->kind;
    return isStringType(k) || k == TK::Array || k == TK::Struct || k == TK::FunctionBlock;
}

TypeTable::TypeTable() {
    struct E { TK k; const char* name; uint32_t size; };
    static const E elems[] = {
        {TK::Bool, "BOOL", 1},   {TK::SInt, "SINT", 1},   {TK::Int, "INT", 2},       {TK::DInt, "DINT", 4},
        {TK::LInt, "LINT", 8},   {TK::USInt, "USINT", 1}, {TK::UInt, "UINT", 2},     {TK::UDInt, "UDINT", 4},
        {TK::ULInt, "ULINT", 8}, {TK::Byte, "BYTE", 1},   {TK::Word, "WORD", 2},     {TK::DWord, "DWORD", 4},
        {TK::LWord, "LWORD", 8}, {TK::Real, "REAL", 4},   {TK::LReal, "LREAL", 8},   {TK::Time, "TIME", 4},
        {TK::LTime, "LTIME", 8}, {TK::Date, "DATE", 4},   {TK::Tod, "TIME_OF_DAY", 4}, {TK::Dt, "DATE_AND_TIME", 4},
        {TK::LDate, "LDATE", 8}, {TK::LTod, "LTIME_OF_DAY", 8}, {TK::LDt, "LDATE_AND_TIME", 8},
        {TK::Char, "CHAR", 1},   {TK::WChar, "WCHAR", 2}, {TK::String, "STRING", 81}, {TK::WString, "WSTRING", 162},
        {TK::Enum, "ENUM", 2},   {TK::Array, "ARRAY", 0}, {TK::Struct, "STRUCT", 0}, {TK::FunctionBlock, "FB", 0},
        {TK::Pointer, "POINTER", 8}, {TK::Reference, "REFERENCE", 8}, {TK::Interface, "INTERFACE", 8},
        {TK::Void, "VOID", 0},
    };
    elementary_.resize(static_cast<size_t>(TK::Void) + 1);
    for (const auto& e : elems) {
        Type t;
        t.kind = e.k;
        t.name = e.name;
        t.size = e.size;
        t.align = std::min<uint32_t>(std::max<uint32_t>(e.size, 1), 8);
        if (e.k == TK::String) { t.maxLen = 80; t.align = 1; }
        if (e.k == TK::WString) { t.maxLen = 80; t.align = 2; }
        storage_.push_back(t);
        elementary_[static_cast<size_t>(e.k)] = &storage_.back();
        names_[e.name] = &storage_.back();
    }
    strings_[{80, false}] = elementary(TK::String);
    strings_[{80, true}] = elementary(TK::WString);
    names_["TOD"] = elementary(TK::Tod);
    names_["DT"] = elementary(TK::Dt);
    names_["LTOD"] = elementary(TK::LTod);
    names_["LDT"] = elementary(TK::LDt);
    names_["BIT"] = elementary(TK::Bool);  // CODESYS/TwinCAT structure bits: a BOOL here (decision 0091)
    // TwinCAT 3's platform-width types, on strun's 64-bit platform; PVOID is
    // an untyped address: any POINTER assigns to it (decision 0095).
    names_["UXINT"] = elementary(TK::ULInt);
    names_["XINT"] = elementary(TK::LInt);
    names_["XWORD"] = elementary(TK::LWord);
    names_["PVOID"] = pointer(elementary(TK::Byte));
    // CODESYS's spelling of the same pseudo types (decision 0434).
    names_["__UXINT"] = elementary(TK::ULInt);
    names_["__XINT"] = elementary(TK::LInt);
    names_["__XWORD"] = elementary(TK::LWord);
    names_.erase("ENUM");
    names_.erase("ARRAY");
    names_.erase("STRUCT");
    names_.erase("FB");
    names_.erase("POINTER");
    names_.erase("REFERENCE");
    names_.erase("INTERFACE");
    names_.erase("VOID");
}

const Type* TypeTable::byName(const std::string& upperName) const {
    auto it = names_.find(upperName);
    return it == names_.end() ? nullptr : it->second;
}

const Type* TypeTable::string(uint32_t maxLen, bool wide) {
    auto key = std::make_pair(maxLen, wide);
    auto it = strings_.find(key);
    if (it != strings_.end()) return it->second;
    Type t;
    t.kind = wide ? TK::WString : TK::String;
    t.name = (wide ? "WSTRING[" : "STRING[") + std::to_string(maxLen) + "]";
    t.maxLen = maxLen;
    t.size = (maxLen + 1) * (wide ? 2 : 1);
    t.align = wide ? 2 : 1;
    storage_.push_back(t);
    strings_[key] = &storage_.back();
    return &storage_.back();
}

const Type* TypeTable::array(const Type* elem, std::vector<ArrayDim> dims, bool flexible) {
    Type t;
    t.kind = TK::Array;
    t.elem = elem;
    t.flexible = flexible;
    uint64_t count = 1;
    std::string name = "ARRAY[";
    for (size_t i = 0; i < dims.size(); ++i) {
        count *= static_cast<uint64_t>(std::max<int64_t>(dims[i].count(), 0));
        if (i) name += ",";
        // ARRAY[*, *]: every dimension is open (its placeholder bounds are not the array's).
        name += flexible ? std::string("*") : std::to_string(dims[i].lo) + ".." + std::to_string(dims[i].hi);
    }
    name += "] OF " + elem->name;
    t.name = name;
    t.dims = std::move(dims);
    t.elemCount = flexible ? 0 : count;
    t.size = flexible ? 0 : static_cast<uint32_t>(count * elem->size);
    t.align = elem->align;
    storage_.push_back(t);
    return &storage_.back();
}

// POINTER TO x and REFERENCE TO x: one 8-byte address type per target, cached.
const Type* TypeTable::indirect(TK kind, const char* spelling, const Type* target, std::map<const Type*, const Type*>& cache) {
    auto it = cache.find(target);
    if (it != cache.end()) return it->second;
    Type t;
    t.kind = kind;
    t.name = spelling + target->name;
    t.target = target;
    t.size = 8;
    // REF_TO ARRAY[*]: the address and the bounds, the descriptor of an
    // ARRAY[*] parameter (decision 0402).
    if (kind == TK::Pointer && target->kind == TK::Array && target->flexible) t.size = 8 + 16 * static_cast<uint32_t>(target->dims.size());
    t.align = 8;
    storage_.push_back(t);
    cache[target] = &storage_.back();
    return &storage_.back();
}

const Type* TypeTable::pointer(const Type* target) { return indirect(TK::Pointer, "POINTER TO ", target, pointers_); }

const Type* TypeTable::refTo(const Type* target) { return indirect(TK::Pointer, "REF_TO ", target, refTos_); }

const Type* TypeTable::reference(const Type* target) { return indirect(TK::Reference, "REFERENCE TO ", target, references_); }

Type* TypeTable::create(Type t) {
    storage_.push_back(std::move(t));
    return &storage_.back();
}

std::string typeName(const Type* t) { return t ? t->name : std::string("?"); }

bool isFlexibleRef(const Type* t) {
    return t && t->kind == TK::Pointer && t->target && t->target->kind == TK::Array && t->target->flexible;
}

bool isBlockOrExtends(const Type* t, const Type* base) {
    if (!t || !base || t->kind != TK::FunctionBlock || base->kind != TK::FunctionBlock) return false;
    for (const Type* p = t; p; p = p->parent)
        if (p == base) return true;
    return false;
}

bool sameType(const Type* a, const Type* b) {
    if (a == b) return true;
    if (!a || !b) return false;
    if (isElementary(a->kind) && isElementary(b->kind)) return a->kind == b->kind;
    if (a->kind == TK::Pointer && b->kind == TK::Pointer) return sameType(a->target, b->target);
    if (a->kind == TK::Reference && b->kind == TK::Reference) return sameType(a->target, b->target);
    if (a->kind == TK::Array && b->kind == TK::Array)
        return sameType(a->elem, b->elem) && a->elemCount == b->elemCount;
    return false;
}

}  // namespace strun::sema
