// symrep/io/ast.h -- the syntax tree of the symrep language.
#pragma once

#include <memory>
#include <string>
#include <vector>

namespace symrep::lang {

/// A node of the syntax tree. Every node remembers where it starts (the token
/// that the error messages point at: the operator for binary operations, the
/// function name for calls, the '[' for indexing).
struct node {
    enum kind_t {
        number,    ///< text: the literal
        string,    ///< text: the unescaped string
        boolean,   ///< text: "true" / "false"
        ident,     ///< text: the name
        unary,     ///< text: "-" or "+"; kids[0]
        binary,    ///< text: + - * / ^ = == != < > <= >=; kids[0], kids[1]
        call,      ///< text: the function name; kids: the arguments
        index,     ///< kids[0][kids[1]]
        list,      ///< kids: the entries
        assign,    ///< text: the variable; kids[0]: the value
    };
    kind_t kind;
    std::string text;
    std::vector<std::unique_ptr<node>> kids;
    int line = 0;
    int column = 0;
};

using node_ptr = std::unique_ptr<node>;

}  // namespace symrep::lang
