// symrep -- the command-line program (placeholder until the language lands).
#include <iostream>
int main() { std::cout << "symrep " SYMREP_VERSION "\n"; return 0; }
