/* The part of Modelica's ModelicaUtilities.h that the cad2mo live view sender uses, for the test
 * harness (a Modelica tool provides the real one). */
#ifndef MODELICA_UTILITIES_H
#define MODELICA_UTILITIES_H
void ModelicaError(const char* string);
void ModelicaFormatWarning(const char* format, ...);
#endif
