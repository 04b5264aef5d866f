// Prints the report CSV of the scene (or shadowed database) named on the command line, as
// `shadowgen report SCENE` does: the shadows generated with the exact method, then area,
// lit area and lit fraction per face and light.

#include <shadowgen/shadowgen.h>

#include <exception>
#include <iostream>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: shadowgen_report SCENE.json (shadowgen " << SHADOWGEN_VERSION << ")\n";
    return 2;
  }
  try {
    const shadowgen::api::Shadows shadows = shadowgen::api::load(argv[1]);
    std::cout << shadowgen::api::report(shadows);
  } catch (const shadowgen::api::InputError& e) {
    std::cerr << "bad input: " << e.what() << '\n';
    return 1;
  } catch (const std::exception& e) {
    std::cerr << e.what() << '\n';
    return 1;
  }
  return 0;
}
