cat "$1/cost.tsv"
