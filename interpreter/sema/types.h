// The IEC type system as the checker and the evaluator see it: every type a
// program can name, with its storage size and layout. Types are created once
// per project by the TypeTable and referred to by plain pointers after that.
#pragma once

#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "interpreter/ast/ast.h"

namespace strun::sema {

enum class TK : uint8_t {
    Bool,
    SInt, Int, DInt, LInt,
    USInt, UInt, UDInt, ULInt,
    Byte, Word, DWord, LWord,
    Real, LReal,
    Time, LTime, Date, Tod, Dt, LDate, LTod, LDt,
    Char, WChar, String, WString,
    Enum, Array, Struct, FunctionBlock, Pointer, Reference, Interface,
    Void,
};

struct Type;
struct PouInfo;

struct ArrayDim {
    int64_t lo = 0, hi = -1;
    int64_t count() const { return hi - lo + 1; }
};

struct Field {
    std::string name;
    const Type* type = nullptr;
    uint32_t offset = 0;
    ast::Loc loc;
    bool hidden = false;  // {attribute 'strun_hidden'} (VarSym::hidden)
};

struct Enumerator {
    std::string name;
    int64_t value = 0;
};

struct Type {
    TK kind = TK::Void;
    std::string name;          // as written/declared ("INT", "MyStruct", "ARRAY[1..3] OF INT")
    uint32_t size = 0;         // bytes
    uint32_t align = 1;
    // STRING / WSTRING: maximum length in characters
    uint32_t maxLen = 0;
    // Enum: the integer base type and the values; Subrange: base kind + range
    const Type* base = nullptr;        // Enum: integer base; alias/subrange: underlying
    std::vector<Enumerator> enumerators;
    bool isSubrange = false;
    int64_t rangeLo = 0, rangeHi = 0;
    // Array
    const Type* elem = nullptr;
    std::vector<ArrayDim> dims;        // empty dims + flexible = ARRAY[*]
    bool flexible = false;             // ARRAY[*] (VAR_IN_OUT, VAR_INPUT; REF_TO ARRAY[*], decision 0402)
    uint64_t elemCount = 0;
    // Struct / FunctionBlock
    std::vector<Field> fields;
    const Type* parent = nullptr;      // STRUCT EXTENDS / FB EXTENDS
    PouInfo* pou = nullptr;            // FunctionBlock
    // Pointer / Reference target
    const Type* target = nullptr;
    // default initial value of an Enum (first enumerator unless given)
    int64_t enumDefault = 0;
    // Enum with {attribute 'strict'}: no integer becomes it (but a constant that is one of its values), no arithmetic (decision 0334).
    bool strictEnum = false;
    // Enum with {attribute 'to_string'}: TO_STRING gives the value's name (TwinCAT, CODESYS).
    bool enumToString = false;
    // Enum / global list with {attribute 'qualified_only'}: its names must be qualified.
    bool qualifiedOnly = false;
    // Initial image of a value of this type when it is not all zeros
    // (structs with member initialisers, enums, aliases with an initial value, FB instances).
    std::vector<uint8_t> defaultImage;
    // Struct / FB whose layout is still being computed: containing it by value
    // (directly, through an array or another type) is a cycle (checker_cycles.cpp).
    bool incomplete = false;
    // TIME / LTIME of a TwinCAT project: an unsigned count of milliseconds /
    // nanoseconds as TwinCAT keeps it, compared, divided and printed
    // unsigned (decision 0367).
    bool unsignedDuration = false;

    // Member (with the members of `parent`s) and enumeration value by
    // upper-case name: hashed, the names folded once (a structure of
    // 100 000 members checks in linear time). The index follows `fields`
    // and `enumerators` as they grow or are replaced (NameIndex).
    const Field* findField(const std::string& upperName) const;
    const Enumerator* findEnumerator(const std::string& upperName) const;

private:
    // Upper-case name -> position of its first occurrence, for the elements
    // [0, size) of the vector whose data was at `data` (rebuilt when it moved).
    struct NameIndex {
        std::unordered_map<std::string, uint32_t> positions;
        const void* data = nullptr;
        size_t size = 0;
    };
    template <class T>
    static const T* findIn(const std::vector<T>& items, NameIndex& index, const std::string& upperName);
    mutable NameIndex fieldIndex_, enumIndex_;
};

// ---- classification helpers
bool isInteger(TK k);        // SINT..ULINT
bool isSignedInt(TK k);      // SINT..LINT
bool isUnsignedInt(TK k);    // USINT..ULINT
bool isBitString(TK k);      // BYTE..LWORD (not BOOL)
bool isAnyBit(TK k);         // BOOL, BYTE..LWORD
bool isReal(TK k);           // REAL, LREAL
bool isNumeric(TK k);        // integers and reals
bool isTimeLike(TK k);       // TIME, LTIME
bool isDateLike(TK k);       // DATE, TOD, DT and L-forms
bool isStringType(TK k);     // STRING, WSTRING
bool isCharType(TK k);       // CHAR, WCHAR
bool isElementary(TK k);
int bitWidth(TK k);
// Nanoseconds per stored unit of a time/date type (TIME/TOD: ms, DATE/DT: s, L-forms: ns).
int64_t nanosPerUnit(TK k);          // value bits of integers, bit strings, time/date, chars (BOOL = 1)
// Scalars are evaluated as 64-bit integers (int64 bit pattern) or doubles.
bool isIntRep(const Type* t);   // evaluated through Expr::i
bool isRealRep(const Type* t);  // evaluated through Expr::f
bool isAggregate(const Type* t);// string, array, struct, FB: evaluated through Expr::addr

// The unsigned integer of a bit string's width, the integer view of enums/chars.
TK integerView(TK k);

class TypeTable {
public:
    TypeTable();
    const Type* elementary(TK k) const { return elementary_[static_cast<size_t>(k)]; }
    const Type* byName(const std::string& upperName) const;  // elementary names and their aliases
    const Type* string(uint32_t maxLen, bool wide);
    const Type* array(const Type* elem, std::vector<ArrayDim> dims, bool flexible);
    const Type* pointer(const Type* target);
    // The same pointer type written `REF_TO x` (IEC Ed.3, SIMATIC AX): its own
    // object only so that messages name it as written; sameType() and every
    // conversion treat it as POINTER TO x (decision 0427).
    const Type* refTo(const Type* target);
    const Type* reference(const Type* target);
    Type* create(Type t);  // user types (enum, struct, FB, alias, subrange)
    // TIME and LTIME become TwinCAT's unsigned ones (decision 0367); before any user type copies them.
    void makeDurationsUnsigned();
    // STRING / WSTRING without a length: maxLen characters instead of 80
    // (SIMATIC AX: 254, decision 0394). Before any type is declared.
    void setDefaultStringLength(uint32_t maxLen);
    const Type* voidType() const { return elementary(TK::Void); }

private:
    const Type* indirect(TK kind, const char* spelling, const Type* target, std::map<const Type*, const Type*>& cache);
    std::deque<Type> storage_;
    std::vector<const Type*> elementary_;
    std::map<std::string, const Type*> names_;
    std::map<std::pair<uint32_t, bool>, const Type*> strings_;
    std::map<const Type*, const Type*> pointers_, refTos_, references_;
};

std::string upper(std::string s);
void upperInPlace(std::string& s);  // the same folding into a buffer the caller reuses
std::string typeName(const Type* t);
// Same type for assignment purposes: elementary types by kind (strings of any length), others by identity.
bool sameType(const Type* a, const Type* b);
// `t` is the function block `base` or one that EXTENDS it (at any depth): an
// instance CODESYS accepts where a `base` is expected (VAR_IN_OUT, REF=).
bool isBlockOrExtends(const Type* t, const Type* base);
// REF_TO ARRAY[*] OF x: holds an address and bounds (decision 0402).
bool isFlexibleRef(const Type* t);

}  // namespace strun::sema
