// A file without any marker.
/* TASK(M01T1) in a block comment is no marker */
int f() { return 1; }
