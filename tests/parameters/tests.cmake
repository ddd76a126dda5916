# tests of parameters
