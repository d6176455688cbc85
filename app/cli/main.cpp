// shadowlab-cli: headless command-line front end (surfaceless EGL).
int main() { return 0; }
