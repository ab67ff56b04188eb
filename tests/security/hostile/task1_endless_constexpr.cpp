// Hostile: a file that keeps the compiler busy without using much memory: a constant expression of
// 4 * 10^10 steps (two nested loops, each below the compiler's loop limit), evaluated one step at a
// time. GCC 12 gives up after 2^25 steps, some seconds; the test grades it with a compile time limit
// of 2 s, standing for a compile that never ends.
constexpr unsigned long long sum_of_products(unsigned long long n) {
	unsigned long long sum = 0;
	for (unsigned long long i = 0; i < n; i++) {
		for (unsigned long long j = 0; j < n; j++) sum += i * j;
	}
	return sum;
}
constexpr unsigned long long forever = sum_of_products(200000);
