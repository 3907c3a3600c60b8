{{ items }}
{% for s in items %}[{{ s }}]{% endfor %}
%%context
items: ["plain", "it's", "say \"hi\"", "both ' and \"", "back\\slash", "tab\there", "new\nline", "cr\rx", "nul\0x", "bell\ax", "del\x7f"]
