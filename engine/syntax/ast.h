// symrep/syntax/ast.h -- the syntax tree of the symrep language.
#pragma once

#include <memory>
#include <string>
#include <utility>
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
        result,    ///< text: "%", "%%" or "%N" (a previous result, see session::results)
        unary,     ///< text: "-" or "+", or "|" for |kids[0]| (norm of a vector, abs of a scalar); kids[0]
        binary,    ///< text: ^ = == != < > <= >=, x (cross), . (dot); kids[0], kids[1]
        chain,     ///< a run of + - (or * /), left to right: kids[0] op[0] kids[1] op[1] ...;
                   ///< text holds one operator character per step, op_pos their places
        call,      ///< text: the function name; kids: the arguments
        index,     ///< kids[0][kids[1]]
        list,      ///< kids: the entries
        assign,    ///< text: the variable; kids[0]: the value
        declare,   ///< text: "vector" or "positive"; kids: the declared names (ident nodes)
    };
    kind_t kind;
    std::string text;
    std::vector<std::unique_ptr<node>> kids;
    int line = 0;
    int column = 0;
    std::vector<std::pair<int, int>> op_pos;  ///< chain: line, column of each operator
};

using node_ptr = std::unique_ptr<node>;

}  // namespace symrep::lang
