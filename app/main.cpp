#include <iostream>
int main() { std::cout << "frictionlab\n"; }
