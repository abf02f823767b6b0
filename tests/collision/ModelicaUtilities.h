/* The part of Modelica's ModelicaUtilities.h that cad2mo's collision C code uses, for the test
 * harness (a Modelica tool provides the real one). */
#ifndef MODELICA_UTILITIES_H
#define MODELICA_UTILITIES_H
void ModelicaError(const char* string);
#endif
