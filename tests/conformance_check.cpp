// placeholder until the conformance runner lands
int main() { return 0; }
