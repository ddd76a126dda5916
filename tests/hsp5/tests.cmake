# tests of hsp5
