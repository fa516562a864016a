// TASK(M01T1): compute it.
int f() {
  // BEGIN SOLUTION
  int x = 1;
  // BEGIN SOLUTION
  return x;
  // END SOLUTION
}
