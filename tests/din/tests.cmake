# tests of din
