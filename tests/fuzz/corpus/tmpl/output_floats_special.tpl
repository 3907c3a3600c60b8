{{ inf }} {{ ninf }} {{ nan }} {{ [inf, ninf, nan] }} {{ 1e308 * 10 }}
%%context
inf: .inf
ninf: -.inf
nan: .nan
