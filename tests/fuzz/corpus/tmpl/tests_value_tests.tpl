{{ true is true }} {{ 1 is true }} {{ false is false }} {{ 0 is false }} {{ 'abc' is lower }} {{ 'aBc' is lower }} {{ 'ABC' is upper }}
{{ '123' is upper }} {{ 'A1' is upper }} {{ 10 is divisibleby 5 }} {{ 10 is divisibleby(3) }} {{ 4 is even }} {{ 3 is odd }} {{ 3.0 is odd }}
