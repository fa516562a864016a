// TASK(M01T1): fine.
int f() {
  // STUB: return 0;
  // BEGIN SOLUTION
  return 1;  // TASK(M1T2): bad id
  // END SOLUTION
}
