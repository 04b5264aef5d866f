# The median of the numbers read from standard input, separated by spaces or lines (the
# upper one of the middle two for an even count), for the benchmark scripts that time
# runs side by side; sourced.
#
#   echo "3.1 2.9 3.0" | median
median() { tr ' ' '\n' | grep . | sort -g | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }
