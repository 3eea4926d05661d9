#!/bin/sh
# The strun binary links no XPathLexer from ANTLR's static runtime (decision
# 0499): its static initialiser would build an ATN at every start.
#   xpath_lexer_left_out.sh STRUN
strun=$1
command -v nm >/dev/null || { echo "nm (binutils) is needed"; exit 1; }
symbols=$(nm "$strun") || { echo "nm cannot read $strun"; exit 1; }
# The stand-ins (__wrap__ZN10XPathLexer...) are expected; XPathLexer's own symbols are not.
linked=$(printf '%s\n' "$symbols" | grep -E ' _ZN10XPathLexer|_GLOBAL__sub_I__ZN10XPathLexer' | grep -v '__wrap_')
if [ -n "$linked" ]; then
    echo "XPathLexer is linked into strun again (a newer ANTLR's XPath takes other symbols from it?):"
    printf '%s\n' "$linked" | head -5
    exit 1
fi
printf '%s\n' "$symbols" | grep -q '__wrap__ZN10XPathLexerC1E' || { echo "the XPathLexer stand-ins are missing"; exit 1; }
echo "XPathLexer left out"
