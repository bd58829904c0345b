// Must NOT compile: a uv map in long double would be rounded to double by the exact predicates,
// so the traits class rejects it at compile time with a message naming the supported types.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Progressive_embedding/Progressive_embedding_traits_2.h>

typedef CGAL::Simple_cartesian<long double> K;
CGAL::Progressive_embedding::Progressive_embedding_traits_2<K> traits;

int main() { return 0; }
